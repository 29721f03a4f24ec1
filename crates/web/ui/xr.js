// WebXR teleoperation: an `immersive-vr` session in which the headset's and controllers' poses
// go to the server (in the `local-floor` reference space, as WebXR reports them) and the world
// is drawn around the person as the server maps them into it. The server turns the poses into
// the robot's actions (crates/web/src/xr.rs); the page only reports and draws.
import * as THREE from 'three';

// At most one report per action step: the server uses the latest at each.
const REPORT_EVERY_MS = 1000 / 30;
// The xr-standard gamepad: button 0 is the trigger, 4 the A or X button (recenter), axes 2–3
// the thumbstick.
const TRIGGER = 0;
const RECENTER = 4;

// The body frame's axes in WebXR's: ahead (+x) is −z there, left (+y) is −x, up (+z) is +y.
const BODY_TO_XR = new THREE.Matrix4().set(
  0, -1, 0, 0,
  0, 0, 1, 0,
  -1, 0, 0, 0,
  0, 0, 0, 1);

// A device value kept in [lo, 1] (a gamepad may report NaN for an absent axis).
const clamp = (v, lo) => Math.max(lo, Math.min(1, Number.isFinite(v) ? v : 0));

const pose = (t) => [t.position.x, t.position.y, t.position.z,
  t.orientation.x, t.orientation.y, t.orientation.z, t.orientation.w];

export class Xr {
  // `send(message)` goes to the server; `state` is the page's test-visible state.
  constructor(view, send, state) {
    this.view = view;
    this.send = send;
    this.state = state;
    this.rig = null;
    this.recenter = false;
    this.lastReport = -Infinity;
    this.pressed = { left: false, right: false };
    state.xr = { supported: false, presenting: false, reports: 0, rig: null };
  }

  // Shows `button` when the browser offers immersive VR.
  async offer(button) {
    if (!navigator.xr) return;
    const supported = await navigator.xr.isSessionSupported('immersive-vr').catch(() => false);
    this.state.xr.supported = supported;
    if (!supported) return;
    button.hidden = false;
    button.onclick = () => this.enter().catch((e) => this.state.errors.push(`WebXR: ${e.message}`));
  }

  async enter() {
    const session = await navigator.xr.requestSession('immersive-vr',
      { optionalFeatures: ['local-floor'] });
    this.view.renderer.xr.setReferenceSpaceType('local-floor');
    await this.view.renderer.xr.setSession(session);
    this.recenter = true;
    this.state.xr.presenting = true;
    session.addEventListener('end', () => {
      this.state.xr.presenting = false;
      this.view.root.matrixAutoUpdate = true;
    });
  }

  // The server's rig: how device poses map into the body frame.
  rigged(message) {
    this.rig = message;
    this.state.xr.rig = message;
  }

  // Each XR frame: report the devices (throttled) and place the world around the person.
  frame(time, frame) {
    const space = this.view.renderer.xr.getReferenceSpace();
    const viewer = space && frame.getViewerPose(space);
    if (!viewer) return;
    const report = { type: 'xr', head: pose(viewer.transform), recenter: this.recenter };
    for (const source of frame.session.inputSources) {
      const side = source.handedness;
      if (!source.gripSpace || (side !== 'left' && side !== 'right')) continue;
      const grip = frame.getPose(source.gripSpace, space);
      if (!grip) continue;
      const pad = source.gamepad;
      report[side] = {
        pose: pose(grip.transform),
        trigger: clamp(pad?.buttons[TRIGGER]?.value ?? 0, 0),
        stick: [clamp(pad?.axes[2] ?? 0, -1), clamp(pad?.axes[3] ?? 0, -1)],
      };
      const recenter = pad?.buttons[RECENTER]?.pressed ?? false;
      if (recenter && !this.pressed[side]) report.recenter = true;
      this.pressed[side] = recenter;
    }
    if (report.recenter || time - this.lastReport >= REPORT_EVERY_MS) {
      this.send(report);
      this.lastReport = time;
      this.recenter = false;
      this.state.xr.reports += 1;
    }
    this.place();
  }

  // The world moved so that the body frame, as the rig maps it, surrounds the person: world →
  // body (the robot's body pose undone) → the rig undone → WebXR's axes.
  place() {
    const body = this.view.robot;
    if (!this.rig || !body) return;
    const root = this.view.root;
    root.matrixAutoUpdate = false;
    const worldToBody = new THREE.Matrix4().compose(body.position, body.quaternion,
      new THREE.Vector3(1, 1, 1)).invert();
    const [x, y, z] = this.rig.offset;
    const unOffset = new THREE.Matrix4().makeTranslation(-x, -y, -z);
    const unTurn = new THREE.Matrix4().makeRotationZ(-this.rig.yaw);
    root.matrix.copy(BODY_TO_XR).multiply(unTurn).multiply(unOffset).multiply(worldToBody);
    root.matrixWorldNeedsUpdate = true;
  }
}
