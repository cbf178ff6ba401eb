// photowalk's web page (photowalk share): the model and what photowalk knows of it are
// inside the page (#pw-meta: viewpoints, navigation, tour, dimensions; #pw-model: the
// binary glTF, base64), so it opens from file:// with no server and no network.
//
// Keys as photowalk walk: mouse look (click: pointer lock), W A S D and the arrows,
// Shift to run, PageUp/PageDown the viewpoints, T the tour. On a touch screen: drag to
// look, the thumb pad to walk.
//
// For tests and tools, window.photowalk: ready (a promise), viewpoints, goTo(i),
// state(), placeAt(eye, yaw), playTour(), fps() (frames drawn in the last second).
import * as THREE from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { Avatar, CollisionWorld } from './avatar.js';
import { applyProjection } from './camera.js';
import { buildUi } from './ui.js';

function base64Bytes(text) {
  const binary = atob(text.replace(/\s+/g, ''));
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
  return bytes.buffer;
}

function collectTriangles(root) {
  const out = [];
  const v = new THREE.Vector3();
  root.updateMatrixWorld(true);
  root.traverse((object) => {
    if (!object.isMesh || !object.geometry) return;
    const position = object.geometry.getAttribute('position');
    if (!position) return;
    const index = object.geometry.getIndex();
    const count = index ? index.count : position.count;
    for (let i = 0; i + 2 < count; i += 3) {
      for (let c = 0; c < 3; ++c) {
        v.fromBufferAttribute(position, index ? index.getX(i + c) : i + c).applyMatrix4(object.matrixWorld);
        out.push(v.x, v.y, v.z);
      }
    }
  });
  return new Float64Array(out);
}

function forwardOf(orientation) {
  const q = new THREE.Quaternion(orientation[0], orientation[1], orientation[2], orientation[3]);
  const f = new THREE.Vector3(0, 0, -1).applyQuaternion(q);
  return [f.x, f.y, f.z];
}

async function start() {
  const meta = JSON.parse(document.getElementById('pw-meta').textContent);
  const glb = base64Bytes(document.getElementById('pw-model').textContent);

  const renderer = new THREE.WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
  renderer.setPixelRatio(1);
  renderer.toneMapping = THREE.NoToneMapping;
  renderer.outputColorSpace = THREE.SRGBColorSpace;
  document.body.appendChild(renderer.domElement);

  const scene = new THREE.Scene();
  const bg = meta.background || [0, 0, 0];
  scene.background = new THREE.Color().setRGB(bg[0], bg[1], bg[2], THREE.SRGBColorSpace);
  const gltf = await new GLTFLoader().parseAsync(glb, '');
  scene.add(gltf.scene);
  // Lit materials (imported scenes): the headlight photowalk's renderer has, and a
  // little ambient light so that nothing is black. The photo's textures are unlit.
  const camera = new THREE.PerspectiveCamera(50, 1, meta.near || 0.05, meta.far || 2000);
  scene.add(camera);
  if (meta.navigation.headlight) camera.add(new THREE.DirectionalLight(0xffffff, 1.0));
  scene.add(new THREE.AmbientLight(0xffffff, 0.2));

  const world = new CollisionWorld(collectTriangles(gltf.scene));
  const avatar = new Avatar(meta.navigation, world);
  const state = { viewpoint: 0, fixed: true, tour: null, frames: [] };

  const resize = () => {
    const w = window.innerWidth, h = window.innerHeight;
    renderer.setSize(w, h, false);
    renderer.domElement.style.width = w + 'px';
    renderer.domElement.style.height = h + 'px';
  };
  window.addEventListener('resize', resize);
  resize();

  // At a viewpoint the view is the viewpoint's own (its lens, roll included) until the
  // person moves; then the avatar's eye, with the viewpoint's field of view.
  const goTo = (i) => {
    const n = meta.viewpoints.length;
    if (n === 0) return;
    state.viewpoint = ((i % n) + n) % n;
    const vp = meta.viewpoints[state.viewpoint];
    avatar.placeAt(vp.position, forwardOf(vp.orientation));
    state.fixed = true;
    state.tour = null;
    ui.showViewpoint(state.viewpoint);
  };

  const keys = new Set();
  const touch = { forward: 0, strafe: 0 };
  const playTour = () => {
    if (!meta.tour || meta.tour.samples.length < 2) return;
    state.tour = { start: performance.now() };
    state.fixed = false;
  };
  const ui = buildUi(meta, { goTo, playTour, touch, canvas: renderer.domElement, look: (dx, dy) => { avatar.look(dx, dy); state.fixed = false; } });

  window.addEventListener('keydown', (e) => {
    if (e.code === 'PageUp') { goTo(state.viewpoint - 1); e.preventDefault(); return; }
    if (e.code === 'PageDown') { goTo(state.viewpoint + 1); e.preventDefault(); return; }
    if (e.code === 'KeyT') { playTour(); return; }
    keys.add(e.code);
  });
  window.addEventListener('keyup', (e) => keys.delete(e.code));
  window.addEventListener('blur', () => keys.clear());

  let last = performance.now();
  const frame = (now) => {
    requestAnimationFrame(frame);
    const dt = Math.min(0.1, Math.max(0, (now - last) / 1000));
    last = now;
    state.frames.push(now);
    while (state.frames.length && state.frames[0] < now - 1000) state.frames.shift();
    const forward = (keys.has('KeyW') || keys.has('ArrowUp') ? 1 : 0) - (keys.has('KeyS') || keys.has('ArrowDown') ? 1 : 0) + touch.forward;
    const strafe = (keys.has('KeyD') || keys.has('ArrowRight') ? 1 : 0) - (keys.has('KeyA') || keys.has('ArrowLeft') ? 1 : 0) + touch.strafe;
    const run = keys.has('ShiftLeft') || keys.has('ShiftRight');
    if (forward !== 0 || strafe !== 0) { state.fixed = false; state.tour = null; }
    if (state.tour) {
      const samples = meta.tour.samples, step = meta.tour.stepS;
      const t = Math.max(0, (now - state.tour.start) / 1000), i = Math.min(samples.length - 1, Math.floor(t / step));
      const s = samples[i];
      avatar.eye = [s[0], s[1], s[2]];
      avatar.yaw = s[3];
      avatar.pitch = 0;
      if (i === samples.length - 1) state.tour = null;
    } else {
      avatar.move(dt, forward, strafe, run);
    }
    const vp = meta.viewpoints[state.viewpoint] || { fov: 0.785, position: [0, 1.6, 0], orientation: [0, 0, 0, 1] };
    if (state.fixed) {
      camera.position.set(vp.position[0], vp.position[1], vp.position[2]);
      camera.quaternion.set(vp.orientation[0], vp.orientation[1], vp.orientation[2], vp.orientation[3]);
      applyProjection(camera, vp, renderer.domElement.width, renderer.domElement.height);
    } else {
      camera.position.set(avatar.eye[0], avatar.eye[1], avatar.eye[2]);
      camera.quaternion.setFromEuler(new THREE.Euler(avatar.pitch, avatar.yaw, 0, 'YXZ'));
      applyProjection(camera, { fov: vp.fov }, renderer.domElement.width, renderer.domElement.height);
    }
    renderer.render(scene, camera);
  };

  goTo(meta.startViewpoint || 0);
  requestAnimationFrame(frame);
  return {
    viewpoints: meta.viewpoints.map((v) => v.description),
    goTo,
    playTour,
    // Tests: the eye put somewhere, looking along `yaw`, as a person walking would be.
    placeAt: (eye, yaw) => { avatar.eye = [...eye]; avatar.yaw = yaw; avatar.pitch = 0; state.fixed = false; state.tour = null; },
    state: () => ({ eye: [...avatar.eye], yaw: avatar.yaw, pitch: avatar.pitch, viewpoint: state.viewpoint, fixed: state.fixed, touring: !!state.tour }),
    fps: () => state.frames.length,
  };
}

const ready = start().catch((error) => {
  const div = document.createElement('div');
  div.className = 'pw-error';
  div.textContent = 'photowalk: this page could not show its model: ' + error.message;
  document.body.appendChild(div);
  throw error;
});
window.photowalk = { ready };
ready.then((api) => Object.assign(window.photowalk, api));
