// What both browser tests need: `behavior serve` on a free port, and Debian's headless
// Chromium launched by Playwright through `executablePath` (browser downloads do not work
// here), drawing with SwiftShader.
import { chromium } from 'playwright-core';
import { spawn } from 'node:child_process';
import { resolve } from 'node:path';

export const BIN = resolve(process.env.BEHAVIOR_BIN ?? 'target/release/behavior');
const CHROMIUM = process.env.CHROMIUM ?? '/usr/bin/chromium';

// `behavior serve ACTIVITY --seed SEED [ARGS...]` recording into `demos`.
export function startServer(demos, { activity = 'bringing_in_wood', seed = 1, args = [] } = {}) {
  return start(['serve', activity, '--seed', String(seed), '--port', '0', '--record-dir', demos,
    ...args]);
}

// `behavior view RECORDING`.
export function startViewer(recording) {
  return start(['view', recording, '--port', '0']);
}

// `behavior ARGS...`: `address` resolves to the page's URL once it listens; `stopped` to its
// exit code and output.
function start(args) {
  const server = spawn(BIN, args, { stdio: ['ignore', 'pipe', 'inherit'] });
  let out = '';
  const address = new Promise((ok, fail) => {
    server.stdout.on('data', (chunk) => {
      out += chunk;
      const found = out.match(/on (http:\/\/[\d.:]+\/)/);
      if (found) ok(found[1]);
    });
    server.on('exit', (code) => fail(new Error(`behavior ${args[0]} exited (${code}): ${out}`)));
  });
  const stopped = new Promise((ok) => server.on('exit', (code) => ok({ code, out })));
  return { server, address, stopped };
}

export function launchBrowser() {
  return chromium.launch({
    executablePath: CHROMIUM,
    args: ['--no-sandbox', '--use-gl=angle', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
      '--disable-background-networking', '--disable-component-update', '--disable-sync', '--no-first-run'],
  });
}
