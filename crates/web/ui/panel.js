// The side panel: the activity, Q over time, the goal as a checklist of ground literals that
// tick as they come true, and the efficiency metrics.
const METRICS = [
  ['steps', 'steps', (v) => v],
  ['sim_time_s', 'simulated time', (v) => `${v.toFixed(1)} s`],
  ['distance_navigated', 'distance navigated', (v) => `${v.toFixed(2)} m`],
  ['hand_displacement_left', 'left hand moved', (v) => `${v.toFixed(2)} m`],
  ['hand_displacement_right', 'right hand moved', (v) => `${v.toFixed(2)} m`],
  ['work', 'work', (v) => `${v.toFixed(1)} J`],
  ['kinematic_disarrangement', 'kinematic disarrangement', (v) => `${v.toFixed(3)} m`],
  ['logical_disarrangement', 'logical disarrangement', (v) => v],
];

const $ = (id) => document.getElementById(id);

export class Panel {
  constructor() {
    this.qs = [];
    this.literals = [];
  }

  connection(text) { $('connection').textContent = text; }

  hand(side) { $('hand').textContent = `the keys move the ${side} hand`; }

  scene(description) {
    $('activity').textContent = description.activity;
    $('where').textContent =
      `${description.scene} · seed ${description.seed} · episode ${description.episode}`;
    this.literals = description.literals;
    // Q by step; kept when the same episode's scene comes again (a recording scrubbed back).
    const episode = `${description.activity} ${description.seed} ${description.episode}`;
    if (episode !== this.episode) this.qs = [];
    this.episode = episode;
    $('ended').hidden = true;
  }

  status(status) {
    $('q').textContent = status.q.toFixed(3);
    $('step').textContent = `step ${status.step}${status.success ? ' · done' : ''}`;
    this.qs[status.step] = status.q;
    this.plot();
    const list = $('checklist');
    const items = status.checklist.option.map((i) => {
      const li = document.createElement('li');
      li.textContent = this.literals[i];
      li.classList.toggle('holds', status.checklist.holds[i]);
      return li;
    });
    list.replaceChildren(...items);
    const rows = METRICS.filter(([key]) => key in status.metrics).map(([key, name, show]) => {
      const tr = document.createElement('tr');
      tr.innerHTML = `<td>${name}</td><td>${show(status.metrics[key])}</td>`;
      return tr;
    });
    $('metrics').replaceChildren(...rows);
  }

  ended(message) {
    const box = $('ended');
    box.hidden = false;
    box.textContent = `Episode ended (${message.reason}) after ${message.steps} steps: ` +
      `Q ${message.q.toFixed(3)}${message.success ? ', success' : ''}. ` +
      (message.recording ? `Recorded to ${message.recording}.` : '');
  }

  plot() {
    const canvas = $('q-plot');
    const c = canvas.getContext('2d');
    const { width: w, height: h } = canvas;
    c.clearRect(0, 0, w, h);
    c.strokeStyle = '#8fd694';
    c.beginPath();
    const n = Math.max(this.qs.length - 1, 1);
    this.qs.forEach((q, i) => {
      const x = (i / n) * w;
      const y = h - 2 - q * (h - 4);
      if (i === 0) c.moveTo(x, y); else c.lineTo(x, y);
    });
    c.stroke();
  }
}
