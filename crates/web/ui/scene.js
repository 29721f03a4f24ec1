// The 3-D view: the scene's nodes built once per episode from the server's description, posed
// from each binary frame. The world is z-up; a root group turns it into three.js's y-up.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

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

  // A new episode (or a world whose objects changed): every node rebuilt.
  build(description) {
    for (const node of this.nodes) this.root.remove(node);
    this.nodes = description.nodes.map((node) => {
      const group = new THREE.Group();
      group.name = node.link === null ? node.object : `${node.object}/${node.link}`;
      for (const part of node.parts) group.add(mesh(part));
      this.root.add(group);
      return group;
    });
    const first = description.nodes.findIndex((n) => n.object === description.robot[0] && n.link === null);
    this.robot = first >= 0 ? this.nodes[first] : null;
    this.centred = false;
    this.particleColors = description.particle_colors;
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

  // [node, part, r, g, b, emission] for each surface whose states changed its colour.
  recolor(changes) {
    for (const [node, part, r, g, b, glow] of changes) {
      // A detailed form has a material per colour; its body's is the first.
      const materials = this.nodes[node]?.children[part]?.material;
      const material = Array.isArray(materials) ? materials[0] : materials;
      if (!material) continue;
      material.color.setRGB(r, g, b, THREE.LinearSRGBColorSpace);
      material.emissive.setRGB(r * glow, g * glow, b * glow, THREE.LinearSRGBColorSpace);
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

// A part as the cameras' realistic profile finishes it: its colour in the home's palette and its
// states, roughness and metalness; a detailed form's details (a stem, a cap) in their own colours.
function mesh(part) {
  const [r, g, b] = part.color;
  const color = new THREE.Color().setRGB(r, g, b, THREE.LinearSRGBColorSpace);
  const body = new THREE.MeshStandardMaterial({
    color,
    emissive: color.clone().multiplyScalar(part.emission),
    roughness: part.roughness,
    metalness: part.metallic,
  });
  const m = part.shape.kind === 'form' ? form(part.shape, body) : new THREE.Mesh(geometry(part.shape), body);
  const o = part.offset;
  m.position.set(o[0], o[1], o[2]);
  m.quaternion.set(o[3], o[4], o[5], o[6]);
  return m;
}

// A detailed form in the body's material and its details' own (the body's first, which
// recolouring changes).
function form(shape, body) {
  const materials = [body, ...shape.details.map((d) => new THREE.MeshStandardMaterial({
    color: new THREE.Color().setRGB(d.color[0], d.color[1], d.color[2], THREE.LinearSRGBColorSpace),
    roughness: d.roughness,
    metalness: d.metallic,
  }))];
  return new THREE.Mesh(formGeometry(shape), materials);
}

// A form's geometry: normals averaged over each vertex's triangles (a fold's vertices are its
// own, so it stays sharp), and a group per colour (the body's first).
function formGeometry(level) {
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.Float32BufferAttribute(level.vertices, 3));
  g.setIndex(level.triangles);
  g.computeVertexNormals();
  const body = level.triangles.length - level.details.reduce((n, d) => n + d.count, 0);
  g.addGroup(0, body, 0);
  let start = body;
  level.details.forEach((d, k) => {
    g.addGroup(start, d.count, k + 1);
    start += d.count;
  });
  return g;
}

// Shapes in their own z-up frames (three's cylinders and capsules stand along y: turned).
function geometry(shape) {
  switch (shape.kind) {
    case 'box': {
      const [x, y, z] = shape.half_extents;
      return new THREE.BoxGeometry(2 * x, 2 * y, 2 * z);
    }
    case 'sphere':
      return new THREE.SphereGeometry(shape.radius, 24, 16);
    case 'cylinder':
      return new THREE.CylinderGeometry(shape.radius, shape.radius, 2 * shape.half_height, 24)
        .rotateX(Math.PI / 2);
    case 'capsule':
      return new THREE.CapsuleGeometry(shape.radius, 2 * shape.half_height, 6, 16)
        .rotateX(Math.PI / 2);
    case 'mesh': {
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.Float32BufferAttribute(shape.vertices, 3));
      g.setIndex(shape.triangles);
      const flat = g.toNonIndexed();
      flat.computeVertexNormals();
      return flat;
    }
    default:
      return new THREE.BufferGeometry();
  }
}
