// Checks that a shot can be measured, before any geometry is attempted, so that a
// person gets one line naming what to fix instead of a NaN or a meaningless box.
#pragma once

#include "base/result.h"
#include "metrology/corridor_frame.h"
#include "metrology/shot.h"

namespace pw::metrology {

// The camera of a shot: focal length in pixels (from focal_px, or focal_mm over
// sensor_width_mm times the image width) and principal point. Fails when the image
// size is unknown, the focal length is not a positive finite number, or the
// principal point is not finite.
Result<Intrinsics> shotIntrinsics(const Shot& shot);

// Everything measure and rectify need from a shot, in this order, each failure one
// line: image size positive; focal length, principal point, camera height and
// reference length positive and finite; every corner finite and within one image
// size of the image; no two corners of a plane closer than 0.5 px; no three corners
// of a plane on one line (angle under 0.5 degrees); every plane's quad convex and
// running clockwise on screen in kPlaneCorners order (top-left, top-right,
// bottom-right, bottom-left as seen from inside; a crossed or mirrored quad means
// corners in the wrong order, and the message says which were likely confused:
// far with near, top with bottom, or left with right).
Status checkShot(const Shot& shot);

}  // namespace pw::metrology
