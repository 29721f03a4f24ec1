// A person at the keyboard, as a closed loop: it reads where the page draws the robot and an
// object, holds the keys a person would (Q/E turn, W/S walk, I/K J/L U/O move the right hand,
// Shift for fine moves, Space grips) through Playwright's keyboard, and looks again after each
// frame. It knows only what the page shows; the server sees real key presses, sent as the
// page sends them.
//
// The grasp is the one a person makes with the keys alone (they move the hand, not turn it):
// the hand raised over the object, palm down, the object under the palm a little ahead of its
// centre (the fingers close over it there), lowered until it rests on the object, the grip
// held, then lifted.

// How the keys move the right hand in the body frame: [+, −] per axis (x ahead, y left, z up).
const HAND_KEYS = [['KeyI', 'KeyK'], ['KeyJ', 'KeyL'], ['KeyU', 'KeyO']];
// Where the object sits under the palm: this far ahead of the palm's centre, m.
const UNDER_PALM = 0.03;
// Over the object before the descent, m above its centre.
const HOVER = 0.12;
// Close enough, m or rad: a fine key press moves a hand 1 cm a step.
const TOLERANCE = 0.01;

const yawOf = (pose) => 2 * Math.atan2(pose[5], pose[6]);
const wrap = (a) => Math.atan2(Math.sin(a), Math.cos(a));

// `point - origin` in the frame of `body` (x ahead, y left, z up).
function inBody(body, point, origin) {
  const yaw = yawOf(body);
  const dx = point[0] - origin[0];
  const dy = point[1] - origin[1];
  return [Math.cos(yaw) * dx + Math.sin(yaw) * dy, -Math.sin(yaw) * dx + Math.cos(yaw) * dy,
    point[2] - origin[2]];
}

export class Pilot {
  // `names`: the page's nodes for the body, the right hand and the object.
  constructor(page, names, log) {
    this.page = page;
    this.names = names;
    this.log = log;
    this.held = new Set();
    this.trace = [];
  }

  // The page's view now: frame count, step and the three poses.
  look() {
    return this.page.evaluate(({ body, hand, object }) => ({
      frames: behavior.frames, step: behavior.step, body: behavior.position(body),
      hand: behavior.position(hand), object: behavior.position(object),
    }), this.names);
  }

  // Holds exactly the keys in `want`.
  async hold(want) {
    for (const key of [...this.held]) {
      if (!want.has(key)) { await this.page.keyboard.up(key); this.held.delete(key); }
    }
    for (const key of want) {
      if (!this.held.has(key)) { await this.page.keyboard.down(key); this.held.add(key); }
    }
  }

  // Runs `decide(view)` once per frame until it returns null (done); it returns the keys to
  // hold. Then releases them, unless `keep`. Throws with the last views if it takes more than
  // `frames` frames.
  async until(what, frames, decide, keep = false) {
    for (let i = 0; i < frames; i++) {
      const view = await this.look();
      const keys = decide(view);
      this.trace.push(`${what} step ${view.step}: body ${fmt(view.body)} hand ${fmt(view.hand)} ` +
        `object ${fmt(view.object)} keys ${[...(keys ?? [])].join('+')}`);
      if (keys === null) {
        if (!keep) await this.hold(new Set());
        this.log(`${what}: done at step ${view.step}`);
        return view;
      }
      await this.hold(keys);
      await this.page.waitForFunction((n) => behavior.frames > n, view.frames, { timeout: 10_000 });
    }
    await this.hold(new Set());
    throw new Error(`${what}: not done in ${frames} frames; last views:\n${this.trace.slice(-8).join('\n')}`);
  }

  // Turns the body until the object is ahead of the right hand's side.
  face(offset = 0.2) {
    return this.until('turn', 300, ({ body, object }) => {
      const [x, y] = inBody(body, object, body);
      const error = wrap(Math.atan2(y + offset, x));
      if (Math.abs(error) < 0.05) return null;
      return new Set([error > 0 ? 'KeyQ' : 'KeyE', ...(Math.abs(error) < 0.3 ? ['ShiftLeft'] : [])]);
    });
  }

  // Walks until the object is `distance` ahead of the body.
  approach(distance = 0.5) {
    return this.until('walk', 300, ({ body, object }) => {
      const error = inBody(body, object, body)[0] - distance;
      if (Math.abs(error) < 0.03) return null;
      return new Set([error > 0 ? 'KeyW' : 'KeyS', ...(Math.abs(error) < 0.15 ? ['ShiftLeft'] : [])]);
    });
  }

  // Moves the right hand (fine keys) until it is at `goal(view)`, or stops moving down while
  // asked to (it rests on something).
  reach(what, goal) {
    let lastZ = Infinity;
    let still = 0;
    return this.until(what, 300, (view) => {
      const error = inBody(view.body, goal(view), view.hand);
      still = error[2] < -TOLERANCE && Math.abs(view.hand[2] - lastZ) < 0.002 ? still + 1 : 0;
      lastZ = view.hand[2];
      const keys = new Set(['ShiftLeft']);
      error.forEach((e, axis) => {
        if (Math.abs(e) > TOLERANCE) keys.add(HAND_KEYS[axis][e > 0 ? 0 : 1]);
      });
      return keys.size === 1 || still > 3 ? null : keys;
    });
  }

  // Raises the right hand, carries it over the object, lowers it onto it.
  async handOnto() {
    const under = ({ body, object }, height) => {
      const yaw = yawOf(body);
      return [object[0] - UNDER_PALM * Math.cos(yaw), object[1] - UNDER_PALM * Math.sin(yaw),
        object[2] + height];
    };
    await this.reach('raise the hand', ({ hand, object }) => [hand[0], hand[1], object[2] + HOVER]);
    await this.reach('over the object', (view) => under(view, HOVER));
    return this.reach('lower onto it', (view) => under(view, 0.02));
  }

  // Holds the grip for `frames` frames, then lifts the hand for `lift` frames; the grip stays
  // held (release it with `hold(new Set())`).
  async gripAndLift(frames = 15, lift = 30) {
    const start = (await this.look()).frames;
    await this.until('grip', frames + 60, ({ frames: now }) =>
      (now - start >= frames ? null : new Set(['Space'])), true);
    const lifted = (await this.look()).frames;
    return this.until('lift', lift + 60, ({ frames: now }) =>
      (now - lifted >= lift ? null : new Set(['Space', 'KeyU', 'ShiftLeft'])), true);
  }
}

function fmt(pose) {
  return pose ? pose.slice(0, 3).map((v) => v.toFixed(3)).join(',') : 'gone';
}
