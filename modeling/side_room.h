// Side openings (issue 25): a doorway, an archway or a corridor's mouth in a side wall,
// which `build` otherwise paints flat on the wall, so that from anywhere but the photo's
// camera the room beyond is a picture on the wall (the largest wrong region of many
// novel views: README "Views from elsewhere").
//
// A person outlines the opening in the photo (a cutout with "shape": "opening": a
// rectangle around it, or its four corners). The outline's corners, taken onto the side
// wall's plane, give the opening: the rectangle on the wall (along the corridor and up)
// they span, down to the floor where they reach within kFloorSnapM of it. The wall is
// opened there and a room built behind: its back wall parallel to the corridor
// kRoomDepthM beyond the wall, its floor and ceiling level with the corridor's, its two ends
// across the corridor as far along as the photo sees through the opening. Each of the
// room's surfaces is cut from the photo where the photo's camera sees it through the
// opening, and elsewhere takes the mean of what the photo shows of it; a surface the photo
// does not see at all takes the mean of the photo through the opening (the floor: the
// corridor floor's). So from the photo's camera the model still gives the photo back,
// and from elsewhere the room has depth and a person can walk into it.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <opencv2/core.hpp>

#include "base/result.h"
#include "engine/scene/image.h"
#include "metrology/measure.h"
#include "metrology/shot.h"
#include "modeling/panel.h"
#include "modeling/surfaces.h"

namespace pw::modeling {

struct RoomPanel {
  std::string label;  // "back", "floor", "ceiling", "far_end", "near_end", "wall_back"
  Panel panel;        // extent = textureRect: the texture covers it
  engine::Image image;  // RGBA; empty: untextured, in `colour`
  glm::mat3 sourceFromTexCoord{1.0f};  // engine::Texture::sourceFromTexCoord (the photo seen)
  glm::vec3 colour{0.5f};              // RGB 0-1: the mean of what the photo shows of it
  double seenFraction = 0;             // share of its texels the photo sees through the opening
};

struct SideRoom {
  std::string name;
  Surface wall = Surface::kLeftWall;  // kLeftWall or kRightWall
  Rect opening;                       // in the wall's (s, t) (surfaces.h)
  double depthM = 0;                  // from the wall to the room's back wall (kRoomDepthM)
  // The room's back wall, floor, ceiling and two ends, textured; and the corridor's wall
  // seen from inside the room around the opening (its back: the wall's colour).
  std::vector<RoomPanel> panels;
};

// The room's depth, taken: a photo down a corridor seldom shows where a side room's floor
// meets its back wall (a search for that line along the corridor's vanishing point found it
// within 10% for 2 of 11 openings of TUNE scenes with the depth in view of the junction or
// not, most of the rest on a jamb's or a reveal's edge about 1 m in).
inline constexpr double kRoomDepthM = 3.0;
inline constexpr double kFloorSnapM = 0.15;
inline constexpr double kMinOpeningM = 0.2;

// What the room's surfaces the photo does not see take (RGB 0-1): the corridor's walls',
// floor's and ceiling's mean colours (the wall's back around the opening: its wall's).
struct RoomColours {
  glm::vec3 leftWall{0.5f}, rightWall{0.5f}, floor{0.5f};
};

// The opening `cutout` outlines: its wall and its rectangle on it (no room yet: `panels`
// empty), or the error openSideRooms would give for it (the editor's check as a person
// draws one).
Result<SideRoom> placeOpening(const metrology::Measurement& measurement, const metrology::Cutout& cutout, double nearM);

// The rooms behind the openings `openings` (cutouts of shape kOpening) outline in the
// measured corridor seen in `photo` (BGR, 8 bit), one per opening, in their order. Each
// room reaches along the corridor no further than half way to the next opening on its wall.
// `nearM`: how far towards the camera (z > 0) the corridor's walls run in the model.
// Errors name the cutout and say what to do (an outline not on a side wall, an opening
// narrower than kMinOpeningM, two openings overlapping on a wall).
Result<std::vector<SideRoom>> openSideRooms(const cv::Mat& photo, const metrology::Measurement& measurement,
                                            const std::vector<metrology::Cutout>& openings, double nearM,
                                            const RoomColours& colours);

}  // namespace pw::modeling
