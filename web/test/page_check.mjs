// Opens a page `photowalk share` wrote in Debian's Chromium (headless, WebGL on
// SwiftShader) through playwright-core, and reports as JSON on stdout:
//   errors      console errors, page errors and failed requests (none expected)
//   loadMs      from navigation to the model shown (window.photowalk.ready)
//   viewpoints  [{name, psnr}]: each viewpoint's frame against a reference PNG
//               (`photowalk render --viewpoint N --size WxH`), PSNR in dB over RGB
//   viewpointKeys  the viewpoint after PageDown from the first, after PageUp, and after a
//               click on the list's third entry
//   walk        with --walk VIEWPOINT: the eye before and after walking forward with
//               key events (W, then Shift+W until it stops), and where it stopped
//   placeWalks  with --place-walk X,Y,Z,YAW,DISTANCE (repeatable): the eye put there looking
//               along YAW (0: -Z, pi/2: -X), W held until it has gone DISTANCE m or a
//               wall has stopped it; where the eye ended
//   touch       with --touch VIEWPOINT: touch events (Chromium's own, through CDP): a drag
//               on the view, then a thumb held on the pad's upper half; the pad shown,
//               the yaw before and after the drag, the eye before and after the thumb
//   tour        with --tour: whether the tour button started the tour and moved the eye
//   fps         frames drawn in the last second
//
// usage: node web/test/page_check.mjs PAGE.html --size WxH [--reference N=FILE.png ...]
//            [--walk N] [--walk-seconds S] [--place-walk X,Y,Z,YAW,DISTANCE ...] [--touch N] [--tour] [--screenshot-dir DIR] [--chromium PATH]
import { chromium } from 'playwright-core';
import { readFileSync, writeFileSync } from 'node:fs';
import { resolve, join } from 'node:path';
import { pathToFileURL } from 'node:url';

const args = process.argv.slice(2);
const page_path = args.shift();
const opt = { references: {}, size: [640, 360], walk: null, walkSeconds: 120, tour: false, shots: null, chromium: '/usr/bin/chromium', placeWalks: [] };
while (args.length) {
  const a = args.shift();
  if (a === '--size') opt.size = args.shift().split('x').map(Number);
  else if (a === '--reference') { const [n, f] = args.shift().split('='); opt.references[n] = f; }
  else if (a === '--walk') opt.walk = Number(args.shift());
  else if (a === '--walk-seconds') opt.walkSeconds = Number(args.shift());
  else if (a === '--tour') opt.tour = true;
  else if (a === '--touch') opt.touch = Number(args.shift());
  else if (a === '--place-walk') opt.placeWalks.push(args.shift().split(',').map(Number));
  else if (a === '--screenshot-dir') opt.shots = args.shift();
  else if (a === '--chromium') opt.chromium = args.shift();
  else { console.error(`page_check: unknown argument ${a}`); process.exit(2); }
}

const browser = await chromium.launch({
  executablePath: opt.chromium,
  headless: true,
  args: ['--no-sandbox', '--disable-dev-shm-usage', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist'],
});
const report = { errors: [], viewpoints: [] };
try {
  const context = await browser.newContext({
    viewport: { width: opt.size[0], height: opt.size[1] }, deviceScaleFactor: 1, hasTouch: opt.touch !== undefined,
  });
  const page = await context.newPage();
  page.on('console', (m) => { if (m.type() === 'error') report.errors.push('console: ' + m.text()); });
  page.on('pageerror', (e) => report.errors.push('page: ' + e.message));
  page.on('requestfailed', (r) => report.errors.push('request failed: ' + r.url().slice(0, 200)));
  // Only the page itself, and what it makes from its own bytes (blob:, data:).
  page.on('request', (r) => {
    if (!/^(file|data|blob):/.test(r.url())) report.errors.push('network request: ' + r.url().slice(0, 200));
  });
  const started = Date.now();
  await page.goto(pathToFileURL(resolve(page_path)).href);
  await page.waitForFunction(() => window.photowalk && window.photowalk.goTo, null, { timeout: 120000 });
  report.loadMs = Date.now() - started;
  const frames = () => page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
  const state = () => page.evaluate(() => window.photowalk.state());
  // Waits while a key or thumb is held: until the eye is `distance` m from `from`, or has
  // stood still for a second (a wall), at most `maxMs`. A slow machine draws fewer frames
  // and each advances the walk by 0.1 s at most, so the test waits for a distance, not
  // for a time.
  const holdUntilMoved = async (from, distance, maxMs) => {
    let last = await state(), still = 0;
    for (let t = 0; t < maxMs; t += 250) {
      await page.waitForTimeout(250);
      const now = await state();
      if (Math.hypot(now.eye[0] - from[0], now.eye[2] - from[2]) >= distance) return { eye: now, still: false };
      still = Math.hypot(now.eye[0] - last.eye[0], now.eye[2] - last.eye[2]) < 1e-3 ? still + 1 : 0;
      last = now;
      if (still >= 4) return { eye: now, still: true };
    }
    return { eye: last, still: false };
  };
  const names = await page.evaluate(() => window.photowalk.viewpoints);
  for (let i = 0; i < names.length; ++i) {
    await page.evaluate((k) => window.photowalk.goTo(k), i);
    await frames();
    const entry = { name: names[i] };
    if (opt.shots) writeFileSync(join(opt.shots, `page_${i + 1}.png`), await page.locator('canvas').screenshot());
    const reference = opt.references[String(i + 1)];
    if (reference) {
      const url = 'data:image/png;base64,' + readFileSync(reference).toString('base64');
      entry.psnr = await page.evaluate(async (src) => {
        const img = new Image();
        img.src = src;
        await img.decode();
        const c = document.createElement('canvas');
        c.width = img.width;
        c.height = img.height;
        const g = c.getContext('2d', { willReadFrequently: true });
        g.drawImage(img, 0, 0);
        const want = g.getImageData(0, 0, c.width, c.height).data;
        g.clearRect(0, 0, c.width, c.height);
        g.drawImage(document.querySelector('canvas'), 0, 0);
        const got = g.getImageData(0, 0, c.width, c.height).data;
        let sum = 0;
        for (let p = 0; p < want.length; p += 4) {
          for (let k = 0; k < 3; ++k) { const d = want[p + k] - got[p + k]; sum += d * d; }
        }
        const mse = sum / ((want.length / 4) * 3);
        return mse === 0 ? 99 : 10 * Math.log10((255 * 255) / mse);
      }, url);
    }
    report.viewpoints.push(entry);
  }
  // The viewpoints as a person reaches them: PageDown, PageUp, and a click on the list.
  if (names.length > 2) {
    await page.evaluate(() => window.photowalk.goTo(0));
    await page.keyboard.press('PageDown');
    const down = (await state()).viewpoint;
    await page.keyboard.press('PageUp');
    const up = (await state()).viewpoint;
    const folded = !(await page.locator('.pw-panel ul').isVisible());
    if (folded) await page.locator('.pw-panel h1').click();
    await page.locator('.pw-panel li button').nth(2).click();
    if (folded) await page.locator('.pw-panel h1').click(); // as it was
    await frames();
    const clicked = await state();
    report.viewpointKeys = { afterPageDown: down, afterPageUp: up, afterClickingThird: clicked.viewpoint, fixed: clicked.fixed };
  }
  if (opt.walk !== null) {
    await page.evaluate((k) => window.photowalk.goTo(k), opt.walk - 1);
    await frames();
    const before = await state();
    await page.keyboard.down('w');
    const moved = (await holdUntilMoved(before.eye, 1.0, 30000)).eye;
    await page.keyboard.up('w');
    await page.keyboard.down('Shift');
    await page.keyboard.down('w');
    const end = await holdUntilMoved(moved.eye, 1000, opt.walkSeconds * 1000);
    await page.keyboard.up('w');
    await page.keyboard.up('Shift');
    const last = end.eye, still = end.still ? 4 : 0;
    report.walk = { before: before.eye, afterWalking: moved.eye, stopped: last.eye, stoppedStill: still >= 4 };
  }
  report.placeWalks = [];
  for (const [x, y, z, yaw, distance] of opt.placeWalks) {
    await page.evaluate(([e, w]) => window.photowalk.placeAt(e, w), [[x, y, z], yaw]);
    await page.keyboard.down('w');
    await holdUntilMoved([x, y, z], distance, 60000);
    await page.keyboard.up('w');
    await frames();
    report.placeWalks.push((await page.evaluate(() => window.photowalk.state())).eye);
  }
  if (opt.touch !== undefined) {
    const cdp = await context.newCDPSession(page);
    const touch = (type, x, y) => cdp.send('Input.dispatchTouchEvent', { type, touchPoints: type === 'touchEnd' ? [] : [{ x, y, id: 1 }] });
    await page.evaluate((k) => window.photowalk.goTo(k), opt.touch - 1);
    await frames();
    const start = await page.evaluate(() => window.photowalk.state());
    const [w, h] = opt.size;
    await touch('touchStart', w * 0.6, h * 0.5);
    for (let k = 1; k <= 10; ++k) await touch('touchMove', w * 0.6 - 8 * k, h * 0.5);
    await touch('touchEnd');
    await frames();
    const looked = await page.evaluate(() => window.photowalk.state());
    const pad = await page.locator('.pw-pad').boundingBox();
    const before = looked;
    if (pad) {
      await touch('touchStart', pad.x + pad.width / 2, pad.y + pad.height * 0.15);
      await holdUntilMoved(before.eye, 1.0, 30000);
      await touch('touchEnd');
      await frames();
    }
    const walked = await page.evaluate(() => window.photowalk.state());
    report.touch = { padShown: !!pad, yawBefore: start.yaw, yawAfterDrag: looked.yaw, eyeBefore: before.eye, eyeAfterPad: walked.eye };
  }
  if (opt.tour) {
    const before = await page.evaluate(() => window.photowalk.state());
    // A touch screen under 600 px starts with the panel folded: its title unfolds it.
    if (!(await page.locator('button.pw-tour').isVisible())) await page.locator('.pw-panel h1').click();
    await page.locator('button.pw-tour').click();
    await holdUntilMoved(before.eye, 1.0, 20000);
    const during = await state();
    report.tour = { started: during.touring, moved: Math.hypot(during.eye[0] - before.eye[0], during.eye[2] - before.eye[2]) };
  }
  report.fps = await page.evaluate(() => window.photowalk.fps());
} finally {
  await browser.close();
}
console.log(JSON.stringify(report));
