// WebXR teleoperation end to end: `behavior serve` opened in headless Chromium with an emulated
// Meta Quest 3 (the `iwer` package's runtime installed before the page loads), an immersive-vr
// session entered from the page's button, the right controller moved ahead (the right hand
// follows), the left thumbstick pushed (the body walks), the episode ended and its recording
// replayed bit for bit, with the headset's raw poses in it.
//
//   BEHAVIOR_BIN=target/release/behavior node crates/web/ui/tests/xr.mjs
import { BIN, launchBrowser, startServer } from './harness.mjs';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { createRequire } from 'node:module';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import assert from 'node:assert/strict';

const IWER = createRequire(import.meta.url).resolve('iwer/build/iwer.min.js');
const demos = mkdtempSync(join(tmpdir(), 'behavior-xr-'));

function log(...args) { console.log('xr:', ...args); }

// How far `to` is from `from` along the heading of `body` (a pose: x, y, z, qx, qy, qz, qw), m.
function ahead(from, to, body) {
  const yaw = 2 * Math.atan2(body[5], body[6]);
  return (to[0] - from[0]) * Math.cos(yaw) + (to[1] - from[1]) * Math.sin(yaw);
}

async function main() {
  // Seed 2: at seed 1 the body starts facing furniture within half a metre.
  const { server, address, stopped } = startServer(demos, { seed: 2 });
  const url = await address;
  const browser = await launchBrowser();
  try {
    const page = await browser.newPage({ viewport: { width: 1280, height: 720 } });
    const pageErrors = [];
    page.on('pageerror', (e) => pageErrors.push(e.message));
    await page.addInitScript({ path: IWER });
    await page.addInitScript(() => {
      const device = new IWER.XRDevice(IWER.metaQuest3);
      device.installRuntime({ forceInstall: true }); // Chromium has a native navigator.xr with no device
      window.xrDevice = device;
    });
    page.on('console', (m) => process.env.XR_DEBUG && log('console:', m.text()));
    await page.goto(url);
    await page.waitForFunction(() => behavior.loaded() && behavior.frames > 2 && behavior.xr?.supported,
      null, { timeout: 60_000 }).catch(async (e) => {
      const seen = await page.evaluate(() => JSON.stringify({ scene: !!behavior.scene, loaded: behavior.loaded(), frames: behavior.frames, xr: behavior.xr, errors: behavior.errors }));
      throw new Error(`the page did not offer immersive VR: ${seen}; page errors ${pageErrors}: ${e.message}`);
    });
    const [body, , right] = await page.evaluate(() => behavior.scene.robot);
    const where = (name) => page.evaluate((n) => behavior.position(n), name);
    log('immersive-vr offered; entering');
    const entered = Date.now();
    await page.click('#enter-vr');
    await page.waitForFunction(() => behavior.xr.presenting && behavior.xr.rig, null, { timeout: 120_000 });
    const rig = await page.evaluate(() => behavior.xr.rig);
    const rigReports = await page.evaluate(() => behavior.xr.reports);
    log(`session started; the rig came ${((Date.now() - entered) / 1000).toFixed(1)} s after entering, ` +
      `after ${rigReports} device reports; yaw ${rig.yaw.toFixed(3)} rad, offset ${rig.offset.map((v) => v.toFixed(2))}`);

    // Let the hands settle where the controllers are, then move the right one 0.3 m ahead.
    // The simulation runs at 30 Hz in real time: poll rather than wait a fixed time, so that a
    // loaded machine is slower but not wrong.
    const settled = async (name) => {
      let last = await where(name);
      for (;;) {
        await page.waitForTimeout(300);
        const now = await where(name);
        if (Math.hypot(now[0] - last[0], now[1] - last[1], now[2] - last[2]) < 0.002) return now;
        last = now;
      }
    };
    const until = async (what, test) => {
      const deadline = Date.now() + 120_000;
      while (!(await test())) {
        assert.ok(Date.now() < deadline, `timed out waiting until ${what}`);
        await page.waitForTimeout(100);
      }
    };
    const bodyAt = await settled(body);
    const handAt = await settled(right);
    await page.evaluate(() => {
      const p = xrDevice.controllers.right.position;
      xrDevice.controllers.right.position.set(p.x, p.y, p.z - 0.3);
    });
    await until('the right hand moves', async () => ahead(handAt, await where(right), bodyAt) > 0.1);
    const handMoved = ahead(handAt, await settled(right), bodyAt);
    log(`right controller 0.30 m ahead: the right hand moved ${handMoved.toFixed(2)} m ahead`);
    assert.ok(Math.abs(handMoved - 0.3) < 0.05, `the hand follows the controller (${handMoved})`);

    // The left thumbstick pushed forward walks the body.
    await page.evaluate(() => xrDevice.controllers.left.updateAxes('thumbstick', 0, -1));
    await until('the body walks', async () => ahead(bodyAt, await where(body), bodyAt) > 0.5);
    await page.evaluate(() => xrDevice.controllers.left.updateAxes('thumbstick', 0, 0));
    const walked = ahead(bodyAt, await settled(body), bodyAt);
    log(`left stick forward: the body walked ${walked.toFixed(2)} m ahead`);
    const reports = await page.evaluate(() => behavior.xr.reports);
    log(`${reports} device reports sent`);

    // End the episode from the page (Enter, as on a desktop) and replay it.
    await page.evaluate(() => behavior.send({ type: 'end' }));
    // The page says what it has taken, so the server keeps it only a few frames ahead and the
    // ending reaches it at once (0.5 s measured; a minute before, when a page drawing two eyes
    // on a CPU worked through a backlog first); the deadline is for a slow, busy machine.
    const asked = Date.now();
    await page.waitForFunction(() => behavior.ended.length > 0, null, { timeout: 240_000 });
    log(`the ending came ${((Date.now() - asked) / 1000).toFixed(1)} s after it was asked for`);
    const ended = await page.evaluate(() => behavior.ended[0]);
    log(`ended (${ended.reason}) after ${ended.steps} steps: ${ended.recording}`);
    const replay = JSON.parse(execFileSync(BIN, ['replay', '--verify', '--json', ended.recording]));
    log(`replay: ${replay.frames} steps, identical ${replay.identical}, device reports ${JSON.stringify(replay.devices)}`);
    assert.equal(replay.identical, true);
    // Every step's device was kept: the keyboard's before the session, the headset's after.
    assert.equal(replay.devices.xr + (replay.devices.keys ?? 0), replay.frames);
    assert.ok(replay.devices.xr > 20, 'the headset drove the steps since the session began');
    assert.deepEqual(pageErrors, []);
  } finally {
    await browser.close();
    server.kill('SIGINT');
  }
  const { code, out } = await stopped;
  assert.equal(code, 0, out);
  log('passed');
}

// The recordings are removed when the test passes and kept for a look when it fails.
main().then(() => rmSync(demos, { recursive: true, force: true }), (error) => {
  console.error(error);
  console.error('recordings kept in', demos);
  process.exit(1);
});
