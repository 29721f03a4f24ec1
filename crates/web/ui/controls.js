// Keyboard and gamepad teleoperation: held keys and sticks become rates in [-1, 1] for the
// body, the active hand and the eye; the grip key closes the hand while held. The server
// applies the latest rates to every step, so a message goes only when they change.
const BODY = { KeyW: [0, 1], KeyS: [0, -1], KeyA: [1, 1], KeyD: [1, -1], KeyQ: [5, 1], KeyE: [5, -1] };
const HAND = { KeyI: [0, 1], KeyK: [0, -1], KeyJ: [1, 1], KeyL: [1, -1], KeyU: [2, 1], KeyO: [2, -1] };
const EYE = { KeyR: [4, -1], KeyF: [4, 1] };
const DEAD_ZONE = 0.15;
// Shift held: a fifth of the speed, for fine placing (1 cm per step instead of 5).
const FINE = 0.2;

export class Controls {
  constructor(send, onHand) {
    this.send = send;
    this.onHand = onHand;
    this.held = new Set();
    this.hand = 'right';
    this.last = '';
    onHand(this.hand);
    addEventListener('keydown', (e) => this.key(e, true));
    addEventListener('keyup', (e) => this.key(e, false));
    addEventListener('blur', () => { this.held.clear(); this.poll(); });
  }

  key(event, down) {
    if (event.target instanceof HTMLInputElement) return;
    if (event.code === 'Tab' && down) {
      this.hand = this.hand === 'right' ? 'left' : 'right';
      this.onHand(this.hand);
      event.preventDefault();
      return;
    }
    if (event.code === 'Enter' && down && !event.repeat) {
      this.send({ type: 'end' });
      return;
    }
    if (event.code === 'Space') event.preventDefault();
    if (down) this.held.add(event.code); else this.held.delete(event.code);
    this.poll();
  }

  // The rates now, from keys and the first gamepad; sent when they differ from the last sent.
  poll() {
    const drive = { type: 'drive', body: [0, 0, 0, 0, 0, 0], eye: [0, 0, 0, 0, 0, 0],
      left: [0, 0, 0, 0, 0, 0], right: [0, 0, 0, 0, 0, 0], grip: [-1, -1] };
    const hand = drive[this.hand];
    for (const code of this.held) {
      if (BODY[code]) drive.body[BODY[code][0]] += BODY[code][1];
      if (HAND[code]) hand[HAND[code][0]] += HAND[code][1];
      if (EYE[code]) drive.eye[EYE[code][0]] += EYE[code][1];
    }
    if (this.held.has('Space')) drive.grip[this.hand === 'left' ? 0 : 1] = 1;
    this.gamepad(drive);
    const scale = this.held.has('ShiftLeft') || this.held.has('ShiftRight') ? FINE : 1;
    for (const key of ['body', 'eye', 'left', 'right', 'grip']) {
      const s = key === 'grip' ? 1 : scale;
      drive[key] = drive[key].map((v) => Math.max(-1, Math.min(1, v)) * s);
    }
    const text = JSON.stringify(drive);
    if (text !== this.last) {
      this.last = text;
      this.send(drive);
    }
  }

  // The standard mapping: left stick drives, right stick turns and lifts the hand, the
  // triggers grasp, the d-pad moves the active hand.
  gamepad(drive) {
    const pad = navigator.getGamepads ? [...navigator.getGamepads()].find((p) => p) : null;
    if (!pad) return;
    const axis = (i) => (Math.abs(pad.axes[i] ?? 0) > DEAD_ZONE ? pad.axes[i] : 0);
    const pressed = (i) => pad.buttons[i]?.value ?? 0;
    drive.body[0] -= axis(1);
    drive.body[1] -= axis(0);
    drive.body[5] -= axis(2);
    const hand = drive[this.hand];
    hand[2] -= axis(3);
    hand[0] += pressed(12) - pressed(13);
    hand[1] += pressed(14) - pressed(15);
    if (pressed(6) > 0.5) drive.grip[0] = 1;
    if (pressed(7) > 0.5) drive.grip[1] = 1;
  }
}
