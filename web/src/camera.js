// How photowalk projects (engine/scene/camera.cpp), for three.js: a viewpoint's
// intrinsics drawn into a frame of another size are scaled about the image's centre by
// the ratio of the smaller sides; without intrinsics the field of view spans the
// frame's smaller side (VRML97 6.53). Pixel centres at integer coordinates, origin at
// the top-left pixel's centre, v down.
import { Matrix4 } from 'three';

export function intrinsicsFor(viewpoint, width, height) {
  const k = viewpoint.intrinsics;
  if (k) {
    if (k.width <= 0 || k.height <= 0 || (k.width === width && k.height === height)) return { ...k };
    const s = Math.min(width, height) / Math.min(k.width, k.height);
    return {
      fx: k.fx * s,
      fy: k.fy * s,
      cu: 0.5 * width - 0.5 + s * (k.cu + 0.5 - 0.5 * k.width),
      cv: 0.5 * height - 0.5 + s * (k.cv + 0.5 - 0.5 * k.height),
      width,
      height,
    };
  }
  const fov = Math.min(Math.max(viewpoint.fov, 1e-4), 3.1);
  const focal = (0.5 * Math.min(width, height)) / Math.tan(0.5 * fov);
  return { fx: focal, fy: focal, cu: (width - 1) * 0.5, cv: (height - 1) * 0.5, width, height };
}

// The OpenGL projection (clip y up, depth -1..1) that puts a camera-space point where
// the intrinsics put its pixel.
export function projectionFrom(k, near, far) {
  const m = new Matrix4();
  m.set(
    (2 * k.fx) / k.width, 0, -((2 * (k.cu + 0.5)) / k.width - 1), 0,
    0, (2 * k.fy) / k.height, -(1 - (2 * (k.cv + 0.5)) / k.height), 0,
    0, 0, -(far + near) / (far - near), (-2 * far * near) / (far - near),
    0, 0, -1, 0,
  );
  return m;
}

export function applyProjection(camera, viewpoint, width, height) {
  const k = intrinsicsFor(viewpoint, width, height);
  camera.projectionMatrix.copy(projectionFrom(k, camera.near, camera.far));
  camera.projectionMatrixInverse.copy(camera.projectionMatrix).invert();
}
