// The page's entry: one websocket to the server, its messages handed to the 3-D view, the
// panel and the controls. `window.behavior` exposes what the page knows, for tests and for the
// browser's console.
import { View } from '/scene.js';
import { Panel } from '/panel.js';
import { Controls } from '/controls.js';
import { Xr } from '/xr.js';
import { Timeline } from '/timeline.js';

const state = {
  connected: false, driving: false, scene: null, step: 0, q: 0, success: false,
  checklist: null, frames: 0, errors: [], ended: [],
};
window.behavior = state;

const view = new View(document.getElementById('view'));
const panel = new Panel();
const watching = new URLSearchParams(location.search).has('watch');
const socket = new WebSocket(
  `${location.protocol === 'https:' ? 'wss' : 'ws'}://${location.host}/ws${watching ? '?watch' : ''}`);
socket.binaryType = 'arraybuffer';
const controls = new Controls((message) => {
  if (state.driving && socket.readyState === WebSocket.OPEN) socket.send(JSON.stringify(message));
}, (hand) => panel.hand(hand));
const xr = new Xr(view, (message) => {
  if (state.driving && socket.readyState === WebSocket.OPEN) socket.send(JSON.stringify(message));
}, state);
xr.offer(document.getElementById('enter-vr'));
// `behavior view`: the recording's timeline; any page may move it.
const timeline = new Timeline((message) => {
  if (socket.readyState === WebSocket.OPEN) socket.send(JSON.stringify(message));
});
state.send = (message) => socket.send(typeof message === 'string' ? message : JSON.stringify(message));
// Where a node is in the world (z up), and how many triangles the last frame drew: for tests.
state.position = (name) => {
  const node = view.nodes.find((n) => n.name === name);
  return node && node.visible ? [...node.position.toArray(), ...node.quaternion.toArray()] : null;
};
state.triangles = () => view.renderer.info.render.triangles;
// Whether the scene's glTF file has been loaded and drawn from, and the images it brought.
state.loaded = () => !!state.scene && view.loaded === state.scene.gltf;
state.textures = () => view.renderer.info.memory.textures;

socket.onopen = () => { state.connected = true; panel.connection('connected'); };
socket.onclose = () => { state.connected = false; panel.connection('disconnected: reload to join again'); };
socket.onmessage = (event) => {
  if (event.data instanceof ArrayBuffer) {
    state.step = view.frame(event.data);
    state.frames += 1;
    // Said after every frame: the server keeps a page that is slow to take them (a headset
    // drawn on a CPU) only a few frames ahead, so its rig and the episode's end are not stuck
    // behind a backlog.
    socket.send(JSON.stringify({ type: 'seen', frames: state.frames }));
    return;
  }
  const message = JSON.parse(event.data);
  switch (message.type) {
    case 'role':
      state.driving = message.driving;
      panel.connection(message.driving ? 'connected: you drive the robot' : 'connected: watching');
      break;
    case 'scene':
      state.scene = message;
      view.build(message);
      panel.scene(message);
      break;
    case 'status':
      Object.assign(state, { q: message.q, success: message.success, checklist: message.checklist,
        metrics: message.metrics, statusStep: message.step });
      view.recolor(message.recolor);
      if (message.particles) {
        view.particles(message.particles);
        state.particles = Object.fromEntries(
          Object.entries(message.particles).map(([kind, flat]) => [kind, flat.length / 3]));
      }
      panel.status(message);
      break;
    case 'ended':
      state.ended.push(message);
      panel.ended(message);
      break;
    case 'timeline':
      if (!state.timeline) panel.connection('connected: playing a recording');
      state.timeline = message;
      timeline.update(message);
      break;
    case 'xr_rig':
      xr.rigged(message);
      break;
    case 'error':
      state.errors.push(message.message);
      console.warn('server:', message.message);
      break;
  }
};

// Every display frame (the headset's, in VR): input, then the view.
function animate(time, frame) {
  if (frame) xr.frame(time, frame);
  else controls.poll();
  view.render();
}
view.renderer.setAnimationLoop(animate);
