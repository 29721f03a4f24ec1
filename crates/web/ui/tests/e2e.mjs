// The viewer end to end in a real browser: `behavior serve` started on a small activity (an
// apple on a kitchen table, `pick_up_apple.bddl`), the page opened in Debian's headless
// Chromium (Playwright drives it through `executablePath`; browser downloads do not work here),
// the home drawn, the robot driven with the keyboard to the apple, the apple grasped and lifted
// with the keys (`pilot.mjs`), the checklist seen ticking, a hostile message refused, the
// episode ended with Enter and its recording replayed bit for bit by `behavior replay
// --verify`, a closed tab's episode kept; then the recording played by `behavior view` and
// scrubbed on its timeline, the apple and the checklist as they were at each step.
//
//   BEHAVIOR_BIN=target/release/behavior node crates/web/ui/tests/e2e.mjs [SCREENSHOT.png]
import { BIN, launchBrowser, startServer, startViewer } from './harness.mjs';
import { Pilot } from './pilot.mjs';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readdirSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import assert from 'node:assert/strict';

const screenshot = process.argv[2];
const demos = mkdtempSync(join(tmpdir(), 'behavior-e2e-'));
const ACTIVITY = join(dirname(fileURLToPath(import.meta.url)), 'pick_up_apple.bddl');
// Seed 8 stands the robot in reach of the apple's table, with nothing between.
const SEED = 8;
const APPLE = 'apple.n.01_1';
const LIFTED = `(not (ontop ${APPLE} table.n.02_1))`;

function log(...args) { console.log('e2e:', ...args); }

const distance = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1]);
const yaw = (p) => 2 * Math.atan2(p[5], p[6]);
const turn = (from, to) => Math.abs(Math.atan2(Math.sin(yaw(to) - yaw(from)), Math.cos(yaw(to) - yaw(from))));

let recorded;

async function main() {
  await drive();
  await view();
  log('passed');
}

async function drive() {
  const { server, address, stopped } = startServer(demos,
    { activity: ACTIVITY, seed: SEED, args: ['--no-clutter'] });
  const url = await address;
  log('server at', url);
  const browser = await launchBrowser();
  try {
    // A small view while driving: SwiftShader draws a 1280×720 frame in about 50 ms, which the
    // key loop would wait for each time it looks.
    const page = await browser.newPage({ viewport: { width: 480, height: 270 } });
    const pageErrors = [];
    page.on('pageerror', (e) => pageErrors.push(e.message));
    await page.goto(url);
    await page.waitForFunction(() => behavior.loaded() && behavior.frames > 2 && behavior.checklist,
      null, { timeout: 60_000 });
    // A frame drawn since the file was loaded.
    const drawn = await page.evaluate(() => behavior.frames);
    await page.waitForFunction((n) => behavior.frames > n, drawn, { timeout: 60_000 });
    const scene = await page.evaluate(() => ({
      driving: behavior.driving, nodes: behavior.scene.nodes.length, textures: behavior.textures(),
      robot: behavior.scene.robot, literals: behavior.scene.literals, triangles: behavior.triangles(),
    }));
    log(`scene: ${scene.nodes} nodes, ${scene.triangles} triangles and ${scene.textures} images drawn, robot ${scene.robot}`);
    // The realistic profile's patterns came in the file, baked into images (wood, floor, walls).
    assert.ok(scene.textures >= 3, `only ${scene.textures} images drawn`);
    assert.equal(scene.driving, true);
    // The page was sent the particles (none in this kitchen: nothing dusty, no water running).
    assert.deepEqual(await page.evaluate(() => behavior.particles), { dust: 0, stain: 0, water: 0 });
    assert.ok(scene.triangles > 1000, `only ${scene.triangles} triangles drawn`);
    const checklist = () => page.evaluate(() => [...document.querySelectorAll('#checklist li')]
      .map((li) => ({ text: li.textContent, holds: li.classList.contains('holds') })));
    const items = await checklist();
    log('checklist:', items.map((i) => `${i.text}${i.holds ? ' ✓' : ''}`).join(' '));
    assert.ok(items.length > 0 && items.every((i) => scene.literals.includes(i.text)), `checklist ${items}`);
    assert.deepEqual(items.find((i) => i.text === LIFTED), { text: LIFTED, holds: false });

    // The keyboard drives: Q/E turn the body toward the apple, W walks to it, the hand keys
    // carry the right hand onto it, Space grips, U lifts.
    const [body, , right] = scene.robot;
    const pilot = new Pilot(page, { body, hand: right, object: APPLE }, log);
    const start = await pilot.look();
    const faced = await pilot.face();
    const turned = turn(start.body, faced.body);
    log(`turned ${turned.toFixed(2)} rad`);
    assert.ok(turned > 0.2, 'Q/E turn the robot');
    await pilot.approach();
    const onto = await pilot.handOnto();
    log(`right hand moved ${distance(start.hand, onto.hand).toFixed(2)} m, rests on the apple`);
    assert.ok(distance(start.hand, onto.hand) > 0.1, 'the hand keys move the hand');
    const lifted = await pilot.gripAndLift();
    const rise = lifted.object[2] - onto.object[2];
    log(`lifted: the apple rose ${rise.toFixed(3)} m with the hand (${(lifted.hand[2] - onto.hand[2]).toFixed(3)} m)`);
    assert.ok(rise > 0.15, `the apple rose only ${rise.toFixed(3)} m: not grasped`);
    await page.waitForFunction((text) => [...document.querySelectorAll('#checklist li.holds')]
      .some((li) => li.textContent === text), LIFTED, { timeout: 60_000 });
    const ticked = await checklist();
    log('checklist:', ticked.map((i) => `${i.text}${i.holds ? ' ✓' : ''}`).join(' '));
    if (screenshot) {
      await page.setViewportSize({ width: 1280, height: 720 });
      await page.waitForTimeout(500);
      await page.screenshot({ path: screenshot });
      log('screenshot', screenshot);
    }

    // A hostile message from the page: refused with a reason, nothing moves.
    const errors = await page.evaluate(() => {
      behavior.send('{"type":"drive","body":[9,0,0,0,0,0]}');
      return behavior.errors.length;
    });
    await page.waitForFunction((n) => behavior.errors.length > n, errors);
    const refusal = await page.evaluate(() => behavior.errors.at(-1));
    log('refused:', refusal);
    assert.match(refusal, /body\[0\]/);

    // Enter ends the episode (the apple still held); its recording replays bit for bit.
    await page.keyboard.press('Enter');
    await pilot.hold(new Set());
    await page.waitForFunction(() => behavior.ended.length > 0, null, { timeout: 60_000 });
    const ended = await page.evaluate(() => behavior.ended[0]);
    log(`ended (${ended.reason}) after ${ended.steps} steps: ${ended.recording}`);
    assert.equal(ended.reason, 'ended by the driver');
    const replay = JSON.parse(execFileSync(BIN, ['replay', '--verify', '--json', ended.recording]));
    recorded = { path: ended.recording, steps: ended.steps };
    log(`replay: ${replay.frames ?? replay.steps} steps, identical ${replay.identical}`);
    assert.equal(replay.identical, true);
    await page.waitForFunction(() => behavior.scene.episode === 2);
    await page.keyboard.down('KeyW');
    await page.waitForTimeout(400);
    await page.keyboard.up('KeyW');
    assert.deepEqual(pageErrors, []);

    // Closing the tab ends the second episode and keeps its recording.
    await page.close();
    await new Promise((ok) => setTimeout(ok, 1000));
    const files = readdirSync(demos).filter((f) => f.endsWith('.mcap'));
    log('recordings:', files.join(', '));
    assert.equal(files.length, 2);
  } finally {
    await browser.close();
    server.kill('SIGINT');
  }
  const { code, out } = await stopped;
  assert.equal(code, 0, out);
  assert.match(out, /2 recording\(s\) written/);
}

// The first episode's recording in `behavior view`: re-simulated, scrubbed to the step the
// apple was lifted at and back to the start.
async function view() {
  const { server, address } = startViewer(recorded.path);
  const browser = await launchBrowser();
  try {
    const page = await browser.newPage({ viewport: { width: 640, height: 360 } });
    await page.goto(await address);
    await page.waitForFunction((steps) => behavior.timeline?.computed === steps && behavior.loaded(),
      recorded.steps, { timeout: 60_000 });
    const timeline = await page.evaluate(() => behavior.timeline);
    log(`view: ${timeline.steps} steps re-simulated, teleoperated ${JSON.stringify(timeline.devices)}, ` +
      `differs from ${timeline.differs_from}`);
    assert.equal(timeline.differs_from, null);
    assert.equal(timeline.devices.keys, recorded.steps);
    assert.match(await page.locator('#recording').textContent(), /teleoperated/);
    const at = async (step) => {
      await page.locator('#scrub').fill(String(step));
      await page.waitForFunction((s) => behavior.step === s && behavior.statusStep === s, step);
      return page.evaluate((apple) => ({ apple: behavior.position(apple),
        ticked: [...document.querySelectorAll('#checklist li.holds')].map((li) => li.textContent) }), APPLE);
    };
    const end = await at(recorded.steps);
    const start = await at(0);
    log(`view: apple at z ${start.apple[2].toFixed(3)} at step 0 (${start.ticked.length} ticked), ` +
      `${end.apple[2].toFixed(3)} at step ${recorded.steps} (ticked: ${end.ticked})`);
    assert.ok(end.apple[2] - start.apple[2] > 0.15, 'the apple is up at the end');
    assert.ok(end.ticked.includes(LIFTED) && !start.ticked.includes(LIFTED));
  } finally {
    await browser.close();
    server.kill('SIGINT');
  }
}

// The recordings are removed when the test passes and kept for a look when it fails.
main().then(() => rmSync(demos, { recursive: true, force: true }), (error) => {
  console.error(error);
  console.error('recordings kept in', demos);
  process.exit(1);
});
