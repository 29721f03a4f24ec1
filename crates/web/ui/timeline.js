// The timeline of a recording played by `behavior view`: play/pause, a slider over the steps
// (up to what the server has re-simulated so far), the rate, and what the recording is — a
// person's teleoperation or an agent's episode, as its device reports say. The server keeps
// the cursor; the page only asks it to move.
const $ = (id) => document.getElementById(id);
const RATES = [0.25, 0.5, 1, 2, 4, 8];

export class Timeline {
  constructor(send) {
    this.send = send;
    this.last = null;
    $('play').addEventListener('click', () => send({ type: this.last?.playing ? 'pause' : 'play' }));
    $('scrub').addEventListener('input', (e) => send({ type: 'seek', step: Number(e.target.value) }));
    const rate = $('rate');
    rate.replaceChildren(...RATES.map((r) => new Option(`${r}×`, String(r), r === 1, r === 1)));
    rate.addEventListener('change', (e) => send({ type: 'rate', rate: Number(e.target.value) }));
    addEventListener('keydown', (e) => {
      if (!this.last || e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement) return;
      if (e.code === 'Space') {
        e.preventDefault();
        send({ type: this.last.playing ? 'pause' : 'play' });
      } else if (e.code === 'ArrowRight' || e.code === 'ArrowLeft') {
        const step = this.last.step + (e.code === 'ArrowRight' ? 1 : -1) * (e.shiftKey ? 30 : 1);
        send({ type: 'seek', step: Math.max(0, Math.min(this.last.computed, step)) });
      }
    });
  }

  update(t) {
    this.last = t;
    $('timeline').hidden = false;
    $('help').hidden = true;
    $('play').textContent = t.playing ? '❚❚' : '▶';
    const scrub = $('scrub');
    scrub.max = String(t.steps);
    // The part not yet re-simulated is drawn lighter; the slider cannot go there.
    const done = t.steps ? (100 * t.computed) / t.steps : 100;
    scrub.style.setProperty('--done', `${done}%`);
    if (document.activeElement !== scrub || !t.playing) scrub.value = String(t.step);
    $('rate').value = String(t.rate);
    $('position').textContent = `step ${t.step} / ${t.steps}` +
      (t.computed < t.steps && !t.stopped ? ` · re-simulated ${t.computed}` : '');
    const devices = Object.entries(t.devices);
    const who = devices.length
      ? `teleoperated (${devices.map(([d, n]) => `${n} steps from ${d}`).join(', ')})`
      : 'an agent\'s or planner\'s episode (no device reports): not human data';
    const notes = [t.recording, who];
    if (t.differs_from !== null) notes.push(`differs from the recording from step ${t.differs_from}`);
    if (t.stopped) notes.push(`stopped: ${t.stopped}`);
    $('recording').textContent = notes.join(' · ');
  }
}
