// The walking person, as photowalk walk has it (editor/walk/avatar.cpp): gravity keeps
// the eye at the avatar's height above the ground below, steps up to the step height
// are climbed, walls stop the body at the avatar's radius and it slides along them.
// The body is a column of spheres from just above the highest step to the eye.

const LOOK_RAD_PER_PX = 0.0025;
const MAX_PITCH_RAD = 1.48;
const GRAVITY_MPS2 = 9.81;
const CELL_M = 2.0;

// Every triangle of the model in world space, in a grid over x and z for the queries.
export class CollisionWorld {
  constructor(triangles) {
    this.triangles = triangles; // Float64Array: 9 numbers per triangle
    this.cells = new Map();
    const count = triangles.length / 9;
    for (let t = 0; t < count; ++t) {
      let x0 = Infinity, x1 = -Infinity, z0 = Infinity, z1 = -Infinity;
      for (let c = 0; c < 3; ++c) {
        const x = triangles[t * 9 + c * 3], z = triangles[t * 9 + c * 3 + 2];
        x0 = Math.min(x0, x); x1 = Math.max(x1, x); z0 = Math.min(z0, z); z1 = Math.max(z1, z);
      }
      if (!(x1 - x0 < 1e6 && z1 - z0 < 1e6)) continue; // not finite, or too large to grid
      for (let i = Math.floor(x0 / CELL_M); i <= Math.floor(x1 / CELL_M); ++i) {
        for (let k = Math.floor(z0 / CELL_M); k <= Math.floor(z1 / CELL_M); ++k) {
          const key = i + ',' + k;
          if (!this.cells.has(key)) this.cells.set(key, []);
          this.cells.get(key).push(t);
        }
      }
    }
  }

  // The triangles whose cells the box about (x, z) of half-size `reach` touches.
  near(x, z, reach) {
    const found = new Set();
    for (let i = Math.floor((x - reach) / CELL_M); i <= Math.floor((x + reach) / CELL_M); ++i) {
      for (let k = Math.floor((z - reach) / CELL_M); k <= Math.floor((z + reach) / CELL_M); ++k) {
        const list = this.cells.get(i + ',' + k);
        if (list) for (const t of list) found.add(t);
      }
    }
    return found;
  }

  // The sphere at `centre` pushed out of every triangle it overlaps (a few rounds:
  // a corner is two walls), so that a move into a wall slides along it.
  pushOut(centre, radius) {
    const p = [centre[0], centre[1], centre[2]];
    for (let round = 0; round < 4; ++round) {
      let moved = false;
      for (const t of this.near(p[0], p[2], radius)) {
        const q = closestOnTriangle(this.triangles, t, p);
        const d = [p[0] - q[0], p[1] - q[1], p[2] - q[2]];
        const dist = Math.hypot(d[0], d[1], d[2]);
        if (dist >= radius || dist < 1e-9) continue;
        const s = (radius - dist) / dist;
        p[0] += d[0] * s; p[2] += d[2] * s; // horizontal only: the body does not climb walls
        moved = true;
      }
      if (!moved) break;
    }
    return p;
  }

  // The highest surface hit by a ray straight down from `from`, or null.
  groundBelow(from, maxDistance) {
    let best = null;
    for (const t of this.near(from[0], from[2], 0)) {
      const y = downHit(this.triangles, t, from);
      if (y !== null && y <= from[1] && from[1] - y <= maxDistance && (best === null || y > best)) best = y;
    }
    return best;
  }
}

function closestOnTriangle(tri, t, p) {
  const o = t * 9;
  const a = [tri[o], tri[o + 1], tri[o + 2]], b = [tri[o + 3], tri[o + 4], tri[o + 5]], c = [tri[o + 6], tri[o + 7], tri[o + 8]];
  const sub = (u, v) => [u[0] - v[0], u[1] - v[1], u[2] - v[2]];
  const dot = (u, v) => u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  const at = (u, v, s) => [u[0] + v[0] * s, u[1] + v[1] * s, u[2] + v[2] * s];
  // Ericson, Real-Time Collision Detection, 5.1.5.
  const ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
  const d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const bp = sub(p, b), d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return at(a, ab, d1 / (d1 - d3));
  const cp = sub(p, c), d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return at(a, ac, d2 / (d2 - d6));
  const va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return at(b, sub(c, b), (d4 - d3) / (d4 - d3 + (d5 - d6)));
  const denom = 1 / (va + vb + vc);
  return at(at(a, ab, vb * denom), ac, vc * denom);
}

// Where the vertical line through `from` meets triangle t (its y), or null.
function downHit(tri, t, from) {
  const o = t * 9;
  const x = from[0], z = from[2];
  const ax = tri[o], az = tri[o + 2], bx = tri[o + 3], bz = tri[o + 5], cx = tri[o + 6], cz = tri[o + 8];
  const det = (bz - cz) * (ax - cx) + (cx - bx) * (az - cz);
  if (Math.abs(det) < 1e-12) return null; // a vertical triangle: a wall
  const l1 = ((bz - cz) * (x - cx) + (cx - bx) * (z - cz)) / det;
  const l2 = ((cz - az) * (x - cx) + (ax - cx) * (z - cz)) / det;
  const l3 = 1 - l1 - l2;
  const eps = -1e-9;
  if (l1 < eps || l2 < eps || l3 < eps) return null;
  return l1 * tri[o + 1] + l2 * tri[o + 4] + l3 * tri[o + 7];
}

export class Avatar {
  constructor(navigation, world) {
    this.world = world;
    this.radius = Math.max(0.05, navigation.avatarRadius);
    this.height = Math.max(0.1, navigation.avatarHeight);
    this.step = Math.max(0, navigation.stepHeight);
    this.speed = Math.max(0.01, navigation.speed);
    this.eye = [0, 1.6, 0];
    this.yaw = 0; // 0 looks along -Z; + turns left
    this.pitch = 0; // + looks up
    this.fall = 0;
    this.grounded = false;
  }

  // The eye exactly at the viewpoint, looking its way (roll dropped); gravity waits
  // until the person next walks, so a viewpoint in the air stays put.
  placeAt(position, forward) {
    this.eye = [...position];
    this.yaw = Math.atan2(-forward[0], -forward[2]);
    this.pitch = Math.asin(Math.max(-1, Math.min(1, forward[1])));
    this.fall = 0;
    this.grounded = false;
  }

  look(dxPx, dyPx) {
    this.yaw -= dxPx * LOOK_RAD_PER_PX;
    this.pitch = Math.max(-MAX_PITCH_RAD, Math.min(MAX_PITCH_RAD, this.pitch - dyPx * LOOK_RAD_PER_PX));
  }

  // One step of `dt` seconds: forward and strafe in -1..1, run twice the speed.
  move(dt, forward, strafe, run) {
    forward = Math.max(-1, Math.min(1, forward));
    strafe = Math.max(-1, Math.min(1, strafe));
    if (forward !== 0 || strafe !== 0) {
      this.grounded = true;
      const ahead = [-Math.sin(this.yaw), -Math.cos(this.yaw)], right = [Math.cos(this.yaw), -Math.sin(this.yaw)];
      let dx = ahead[0] * forward + right[0] * strafe, dz = ahead[1] * forward + right[1] * strafe;
      const len = Math.hypot(dx, dz);
      if (len > 1) { dx /= len; dz /= len; }
      const speed = this.speed * (run ? 2 : 1);
      this.moveBody(dx * speed * dt, dz * speed * dt);
    }
    this.applyGravity(dt);
  }

  moveBody(dx, dz) {
    if (!this.world) { this.eye[0] += dx; this.eye[2] += dz; return; }
    // In steps no longer than the radius, so that no wall is passed through.
    const steps = Math.max(1, Math.ceil(Math.hypot(dx, dz) / (0.5 * this.radius)));
    const lowest = this.eye[1] - this.height + this.step + this.radius;
    const heights = [lowest];
    for (let h = lowest + 1.5 * this.radius; h < this.eye[1]; h += 1.5 * this.radius) heights.push(h);
    if (this.eye[1] > lowest) heights.push(this.eye[1]);
    for (let s = 0; s < steps; ++s) {
      let x = this.eye[0] + dx / steps, z = this.eye[2] + dz / steps;
      for (let pass = 0; pass < 2; ++pass) {
        for (const h of heights) [x, , z] = this.world.pushOut([x, h, z], this.radius);
      }
      this.eye[0] = x;
      this.eye[2] = z;
    }
  }

  applyGravity(dt) {
    if (!this.world || !this.grounded) return;
    const from = [this.eye[0], this.eye[1] - this.height + this.step + 1e-3, this.eye[2]];
    const ground = this.world.groundBelow(from, 1000);
    if (ground === null) return; // nothing below: hover, as over an unfinished model
    const target = ground + this.height;
    if (this.eye[1] <= target) { this.eye[1] = target; this.fall = 0; return; }
    this.fall += GRAVITY_MPS2 * dt;
    this.eye[1] = Math.max(target, this.eye[1] - this.fall * dt);
    if (this.eye[1] === target) this.fall = 0;
  }
}
