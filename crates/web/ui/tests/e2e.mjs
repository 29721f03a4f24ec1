// The viewer end to end in a real browser: `behavior serve` started, the page opened in
// Debian's headless Chromium (Playwright drives it through `executablePath`; browser downloads
// do not work here), the home drawn, the robot driven with the keyboard, a hostile message
// refused, the episode ended with Enter and its recording replayed bit for bit by
// `behavior replay --verify`, and a closed tab's episode kept.
//
//   BEHAVIOR_BIN=target/release/behavior node crates/web/ui/tests/e2e.mjs [SCREENSHOT.png]
import { BIN, launchBrowser, startServer } from './harness.mjs';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readdirSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import assert from 'node:assert/strict';

const screenshot = process.argv[2];
const demos = mkdtempSync(join(tmpdir(), 'behavior-e2e-'));

function log(...args) { console.log('e2e:', ...args); }

const distance = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1]);

async function main() {
  const { server, address, stopped } = startServer(demos);
  const url = await address;
  log('server at', url);
  const browser = await launchBrowser();
  try {
    const page = await browser.newPage({ viewport: { width: 1280, height: 720 } });
    const pageErrors = [];
    page.on('pageerror', (e) => pageErrors.push(e.message));
    await page.goto(url);
    await page.waitForFunction(() => behavior.scene && behavior.frames > 2 && behavior.checklist,
      null, { timeout: 60_000 });
    const scene = await page.evaluate(() => ({
      driving: behavior.driving, nodes: behavior.scene.nodes.length, robot: behavior.scene.robot[0],
      literals: behavior.scene.literals, triangles: behavior.triangles(),
    }));
    log(`scene: ${scene.nodes} nodes, ${scene.triangles} triangles drawn, robot ${scene.robot}`);
    assert.equal(scene.driving, true);
    assert.ok(scene.triangles > 1000, `only ${scene.triangles} triangles drawn`);
    const items = await page.locator('#checklist li').allTextContents();
    assert.ok(items.length > 0 && items.every((t) => scene.literals.includes(t)), `checklist ${items}`);
    log('checklist:', items.join(' '));

    // The keyboard drives: W ahead, then Q turns.
    const where = () => page.evaluate((name) => behavior.position(name), scene.robot);
    const before = await where();
    await page.keyboard.down('KeyW');
    await page.waitForTimeout(800);
    await page.keyboard.up('KeyW');
    await page.keyboard.down('KeyQ');
    await page.waitForTimeout(500);
    await page.keyboard.up('KeyQ');
    await page.waitForTimeout(300);
    const after = await where();
    const yaw = (p) => 2 * Math.atan2(p[5], p[6]);
    log(`robot moved ${distance(before, after).toFixed(2)} m, turned ${(yaw(after) - yaw(before)).toFixed(2)} rad`);
    assert.ok(distance(before, after) > 0.3, 'W moves the robot ahead');
    assert.ok(Math.abs(yaw(after) - yaw(before)) > 0.2, 'Q turns it');
    if (screenshot) {
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

    // Enter ends the episode; its recording replays bit for bit.
    await page.keyboard.press('Enter');
    await page.waitForFunction(() => behavior.ended.length > 0, null, { timeout: 10_000 });
    const ended = await page.evaluate(() => behavior.ended[0]);
    log(`ended (${ended.reason}) after ${ended.steps} steps: ${ended.recording}`);
    assert.equal(ended.reason, 'ended by the driver');
    const replay = JSON.parse(execFileSync(BIN, ['replay', '--verify', '--json', ended.recording]));
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
  log('passed');
}

main().catch((error) => {
  console.error(error);
  process.exit(1);
});
