// The page's panels: title and dimensions, the viewpoints to click, the tour button,
// the keys; on a touch screen a thumb pad to walk and a drag to look.

const STYLE = `
html, body { margin: 0; height: 100%; overflow: hidden; background: #000; font: 14px/1.4 system-ui, sans-serif; }
canvas { display: block; touch-action: none; }
.pw-panel { position: fixed; z-index: 2; left: 8px; top: 8px; max-width: min(340px, 60vw); color: #eee;
  background: rgba(20, 20, 24, 0.72); border-radius: 6px; padding: 8px 10px; }
.pw-panel h1 { font-size: 15px; margin: 0 0 4px; }
.pw-panel ul { list-style: none; margin: 4px 0; padding: 0; }
.pw-panel button { font: inherit; color: #eee; background: rgba(255, 255, 255, 0.08); border: 1px solid #555;
  border-radius: 4px; margin: 1px 0; padding: 2px 8px; cursor: pointer; text-align: left; }
.pw-panel button.pw-current { border-color: #9cf; color: #9cf; }
.pw-dims { white-space: pre-line; color: #ccc; }
.pw-keys { color: #999; font-size: 12px; margin-top: 4px; }
.pw-hidden .pw-body { display: none; }
.pw-pad { position: fixed; z-index: 1; left: 24px; bottom: 24px; width: 120px; height: 120px; border-radius: 60px;
  background: rgba(255, 255, 255, 0.12); border: 2px solid rgba(255, 255, 255, 0.35); touch-action: none; display: none; }
.pw-pad div { position: absolute; left: 40px; top: 40px; width: 40px; height: 40px; border-radius: 20px; background: rgba(255, 255, 255, 0.5); }
.pw-touch .pw-pad { display: block; }
.pw-error { position: fixed; inset: 30% 10% auto; color: #fff; background: #922; padding: 12px; border-radius: 6px; }
`;

export function buildUi(meta, { goTo, playTour, touch, canvas, look }) {
  const style = document.createElement('style');
  style.textContent = STYLE;
  document.head.appendChild(style);

  const panel = document.createElement('div');
  panel.className = 'pw-panel';
  const title = document.createElement('h1');
  title.textContent = meta.title || 'photowalk';
  title.title = 'click to fold';
  title.style.cursor = 'pointer';
  title.addEventListener('click', () => panel.classList.toggle('pw-hidden'));
  panel.appendChild(title);
  const body = document.createElement('div');
  body.className = 'pw-body';
  panel.appendChild(body);
  if (meta.dimensions && meta.dimensions.length) {
    const dims = document.createElement('div');
    dims.className = 'pw-dims';
    dims.textContent = meta.dimensions.join('\n');
    body.appendChild(dims);
  }
  const list = document.createElement('ul');
  const buttons = meta.viewpoints.map((vp, i) => {
    const li = document.createElement('li');
    const b = document.createElement('button');
    b.textContent = vp.description || `Viewpoint ${i + 1}`;
    b.addEventListener('click', (e) => { e.stopPropagation(); goTo(i); });
    li.appendChild(b);
    list.appendChild(li);
    return b;
  });
  body.appendChild(list);
  if (meta.tour && meta.tour.samples.length > 1) {
    const tour = document.createElement('button');
    tour.textContent = '▶ Play the tour (T)';
    tour.className = 'pw-tour';
    tour.addEventListener('click', (e) => { e.stopPropagation(); playTour(); });
    body.appendChild(tour);
  }
  const help = document.createElement('div');
  help.className = 'pw-keys';
  help.textContent = 'Click the view to look with the mouse (Esc frees it). W A S D or arrows: walk, Shift: run, PageUp/PageDown: viewpoints.';
  body.appendChild(help);
  document.body.appendChild(panel);
  // A phone: the view first (the title unfolds the panel).
  if (window.matchMedia('(pointer: coarse)').matches && window.innerWidth < 600) panel.classList.add('pw-hidden');

  // Mouse: pointer lock on click; look while locked.
  canvas.addEventListener('click', () => { if (canvas.requestPointerLock) canvas.requestPointerLock(); });
  document.addEventListener('mousemove', (e) => {
    if (document.pointerLockElement === canvas) look(e.movementX, e.movementY);
  });

  // Touch: a drag on the view looks, the pad walks.
  const pad = document.createElement('div');
  pad.className = 'pw-pad';
  const knob = document.createElement('div');
  pad.appendChild(knob);
  document.body.appendChild(pad);
  let lookTouch = null, padTouch = null;
  const padMove = (t) => {
    const r = pad.getBoundingClientRect();
    let dx = (t.clientX - (r.left + r.width / 2)) / (r.width / 2), dy = (t.clientY - (r.top + r.height / 2)) / (r.height / 2);
    const len = Math.hypot(dx, dy);
    if (len > 1) { dx /= len; dy /= len; }
    touch.strafe = dx;
    touch.forward = -dy;
    knob.style.transform = `translate(${dx * 40}px, ${dy * 40}px)`;
  };
  window.addEventListener('touchstart', () => document.body.classList.add('pw-touch'), { once: true, passive: true });
  pad.addEventListener('touchstart', (e) => { padTouch = e.changedTouches[0].identifier; padMove(e.changedTouches[0]); e.preventDefault(); });
  canvas.addEventListener('touchstart', (e) => { const t = e.changedTouches[0]; lookTouch = { id: t.identifier, x: t.clientX, y: t.clientY }; e.preventDefault(); });
  window.addEventListener('touchmove', (e) => {
    for (const t of e.changedTouches) {
      if (t.identifier === padTouch) padMove(t);
      if (lookTouch && t.identifier === lookTouch.id) {
        look(-(t.clientX - lookTouch.x) * 1.5, -(t.clientY - lookTouch.y) * 1.5);
        lookTouch.x = t.clientX;
        lookTouch.y = t.clientY;
      }
    }
  }, { passive: true });
  const end = (e) => {
    for (const t of e.changedTouches) {
      if (t.identifier === padTouch) { padTouch = null; touch.forward = touch.strafe = 0; knob.style.transform = ''; }
      if (lookTouch && t.identifier === lookTouch.id) lookTouch = null;
    }
  };
  window.addEventListener('touchend', end);
  window.addEventListener('touchcancel', end);

  return {
    showViewpoint(i) { buttons.forEach((b, k) => b.classList.toggle('pw-current', k === i)); },
  };
}
