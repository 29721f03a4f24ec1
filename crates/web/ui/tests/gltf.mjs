// `behavior scene export --gltf` checked by the Khronos glTF validator (npm `gltf-validator`):
// a sampled instance of storing_food (its home, objects and robot, once with each robot) written
// as a .glb must give no errors and no warnings, and hold the meshes and materials it says it
// holds; Fetch's with its real meshes.
//
//   BEHAVIOR_BIN=target/release/behavior node crates/web/ui/tests/gltf.mjs
import { BIN } from './harness.mjs';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import assert from 'node:assert/strict';
import validator from 'gltf-validator';

const dir = mkdtempSync(join(tmpdir(), 'behavior-gltf-'));

// Exports storing_food seed 3 with `robot` and validates it; its triangle count.
async function exported(robot) {
  const file = join(dir, `storing_food-${robot}.glb`);
  execFileSync(BIN, ['scene', 'export', 'storing_food', '--seed', '3', '--robot', robot, '--gltf', file], { stdio: 'inherit' });
  const bytes = new Uint8Array(readFileSync(file));
  const report = await validator.validateBytes(bytes, { maxIssues: 50 });
  const { numErrors, numWarnings, messages } = report.issues;
  for (const m of messages.slice(0, 20)) console.log('gltf:', m.severity, m.code, m.pointer, m.message);
  assert.equal(numErrors, 0, `${numErrors} errors in the exported glTF (${robot})`);
  assert.equal(numWarnings, 0, `${numWarnings} warnings in the exported glTF (${robot})`);
  const info = report.info;
  assert.ok(info.drawCallCount > 200, `only ${info.drawCallCount} draw calls: the home is not all there`);
  assert.ok(info.materialCount >= 20, `only ${info.materialCount} materials`);
  assert.ok(info.totalTriangleCount > 20000, `only ${info.totalTriangleCount} triangles: the forms are not detailed`);
  console.log(`gltf: ${robot}: valid (${bytes.length} bytes, ${info.drawCallCount} draw calls, ${info.totalTriangleCount} triangles, ${info.materialCount} materials)`);
  return info.totalTriangleCount;
}

try {
  const behavior = await exported('behavior');
  // Fetch in its maker's meshes (gymnasium-robotics, fetched at first use): 31,700 triangles
  // where its primitives are a few hundred.
  const fetch = await exported('fetch');
  assert.ok(fetch > behavior + 25000, `Fetch adds ${fetch - behavior} triangles: not its real meshes`);
  console.log('gltf: passed');
} finally {
  rmSync(dir, { recursive: true, force: true });
}
