// The 3-D view: the scene's nodes loaded once per scene from the glTF file the server's
// description names (the cameras' meshes and the realistic profile's materials, patterns baked
// into images), posed from each binary frame. The world is z-up; a root group turns it into
// three.js's y-up.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';

const FLOATS_PER_NODE = 7;

export class View {
  constructor(element) {
    this.element = element;
    this.renderer = new THREE.WebGLRenderer({ antialias: true });
    this.renderer.setPixelRatio(devicePixelRatio);
    this.renderer.xr.enabled = true;
    element.appendChild(this.renderer.domElement);
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(0x1d2025);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x404040, 1.6));
    const sun = new THREE.DirectionalLight(0xffffff, 1.4);
    sun.position.set(3, 10, 4);
    this.scene.add(sun);
    this.root = new THREE.Group();
    this.root.rotation.x = -Math.PI / 2;
    this.scene.add(this.root);
    this.camera = new THREE.PerspectiveCamera(55, 1, 0.05, 200);
    this.camera.position.set(0, 8, 8);
    this.orbit = new OrbitControls(this.camera, this.renderer.domElement);
    this.orbit.enableDamping = true;
    this.nodes = [];
    this.robot = null;
    this.dots = {};
    addEventListener('resize', () => this.resize());
    this.resize();
  }

  resize() {
    const { clientWidth: w, clientHeight: h } = this.element;
    this.renderer.setSize(w, h);
    this.camera.aspect = w / Math.max(h, 1);
    this.camera.updateProjectionMatrix();
  }

  // A new episode (or a world whose objects changed): every node rebuilt from the scene's
  // glTF file, a top node per node of the description, in its order. Frames that come while
  // it loads are kept: the latest poses the nodes once they are there.
  build(description) {
    this.particleColors = description.particle_colors;
    // The same file again (a recording scrubbed within one scene): the nodes stay.
    if (description.gltf === this.wanted) return;
    for (const node of this.nodes) this.root.remove(node);
    this.nodes = [];
    this.robot = null;
    this.loaded = null;
    const wanted = (this.wanted = description.gltf);
    fetch(description.gltf)
      .then((response) => {
        if (!response.ok) throw new Error(`${description.gltf}: ${response.status}`);
        return response.arrayBuffer();
      })
      .then((bytes) => new GLTFLoader().parseAsync(bytes, ''))
      .then((gltf) => {
        if (this.wanted !== wanted) return;
        this.place(description, gltf.scene);
        this.loaded = wanted;
      })
      .catch((error) => {
        console.warn('scene:', error.message);
        this.failed = `${wanted}: ${error.message}`;
      });
  }

  // The file's top nodes (under its z-up root, whose turn our root makes) become the nodes.
  place(description, scene) {
    const top = scene.children[0]?.children ?? [];
    if (top.length !== description.nodes.length) {
      throw new Error(`the scene's file has ${top.length} nodes, its description ${description.nodes.length}`);
    }
    this.nodes = top.slice().map((group, i) => {
      const node = description.nodes[i];
      group.name = node.link === null ? node.object : `${node.object}/${node.link}`;
      // Each part recolours on its own: its materials are its own.
      for (const part of group.children) {
        part.traverse((m) => {
          if (m.material) m.material = m.material.clone();
        });
      }
      this.root.add(group);
      return group;
    });
    const first = description.nodes.findIndex((n) => n.object === description.robot[0] && n.link === null);
    this.robot = first >= 0 ? this.nodes[first] : null;
    this.centred = false;
    if (this.lastFrame) this.frame(this.lastFrame);
    if (this.lastRecolor) this.recolor(this.lastRecolor);
  }

  // Dust, stains and water drops where the server says they are now ({kind: [x, y, z, ...]}),
  // drawn as the cameras draw them: small grey balls, flat dark discs, blue drops.
  particles(particles) {
    for (const [kind, flat] of Object.entries(particles)) {
      const count = flat.length / 3;
      let dots = this.dots[kind];
      if (!dots || dots.capacity < count) {
        if (dots) this.root.remove(dots.mesh);
        const [r, g, b] = this.particleColors?.[kind] ?? [0.5, 0.5, 0.5];
        const color = new THREE.Color().setRGB(r, g, b, THREE.LinearSRGBColorSpace);
        const capacity = Math.max(64, 2 * count);
        const mesh = new THREE.InstancedMesh(DOT_SHAPES[kind](), new THREE.MeshStandardMaterial({ color }), capacity);
        mesh.frustumCulled = false;
        this.root.add(mesh);
        dots = this.dots[kind] = { mesh, capacity };
      }
      const matrix = new THREE.Matrix4();
      for (let i = 0; i < count; i++) {
        dots.mesh.setMatrixAt(i, matrix.makeTranslation(flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]));
      }
      dots.mesh.count = count;
      dots.mesh.instanceMatrix.needsUpdate = true;
    }
  }

  // One frame of poses; returns its step.
  frame(buffer) {
    this.lastFrame = buffer;
    const view = new DataView(buffer);
    const step = view.getUint32(0, true);
    const count = Math.min(this.nodes.length, (buffer.byteLength - 4) / (4 * FLOATS_PER_NODE));
    for (let i = 0; i < count; i++) {
      const at = 4 + i * 4 * FLOATS_PER_NODE;
      const f = (k) => view.getFloat32(at + 4 * k, true);
      const node = this.nodes[i];
      node.visible = !Number.isNaN(f(0));
      if (!node.visible) continue;
      node.position.set(f(0), f(1), f(2));
      node.quaternion.set(f(3), f(4), f(5), f(6));
    }
    this.follow();
    return step;
  }

  // The orbit's centre follows the robot. At an episode's first frame the camera goes above
  // and a little behind it: homes have no ceilings, so from above every room is open.
  follow() {
    if (!this.robot) return;
    const at = this.robot.getWorldPosition(new THREE.Vector3());
    if (!this.centred) {
      const ahead = new THREE.Vector3(1, 0, 0).applyQuaternion(this.robot.getWorldQuaternion(new THREE.Quaternion()));
      ahead.y = 0;
      ahead.normalize();
      this.camera.position.copy(at).addScaledVector(ahead, -1.5).add(new THREE.Vector3(0, 4.5, 0));
      this.orbit.target.copy(at);
      this.centred = true;
    }
    this.camera.position.add(at.clone().sub(this.orbit.target));
    this.orbit.target.copy(at);
  }

  // [node, part, r, g, b, emission] for each surface whose states changed its colour: the
  // part's body material (the one with a reference colour: its image was made for that colour)
  // takes the new colour over its reference.
  recolor(changes) {
    this.lastRecolor = changes;
    for (const [node, part, r, g, b, glow] of changes) {
      this.nodes[node]?.children[part]?.traverse((m) => {
        const reference = m.material?.userData?.reference;
        if (!reference) return;
        const [x, y, z] = reference;
        m.material.color.setRGB(Math.min(r / x, 1), Math.min(g / y, 1), Math.min(b / z, 1), THREE.LinearSRGBColorSpace);
        m.material.emissive.setRGB(r * glow, g * glow, b * glow, THREE.LinearSRGBColorSpace);
      });
    }
  }

  render() {
    this.orbit.update();
    this.renderer.render(this.scene, this.camera);
  }
}

// The particles' shapes, sized as the renderer sizes them (crates/render/src/instances.rs), in
// the z-up world frame.
const DOT_SHAPES = {
  dust: () => new THREE.SphereGeometry(0.008, 6, 4),
  stain: () => new THREE.CylinderGeometry(0.02, 0.02, 0.004, 12).rotateX(Math.PI / 2),
  water: () => new THREE.SphereGeometry(0.009, 6, 4),
};
