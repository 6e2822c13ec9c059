// The 3D view: robots from the cell's merged URDF (urdf-loader), objects, frames.
// The robot frame is z-up; everything hangs under a root turned to three.js's y-up.
// Frames are drawn on demand (render()), not in a loop: an idle page costs nothing.

import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { STLLoader } from 'three/examples/jsm/loaders/STLLoader.js';
import { ColladaLoader } from 'three/examples/jsm/loaders/ColladaLoader.js';
import { OBJLoader } from 'three/examples/jsm/loaders/OBJLoader.js';
import { ConvexGeometry } from 'three/examples/jsm/geometries/ConvexGeometry.js';
import { CSS2DObject, CSS2DRenderer } from 'three/examples/jsm/renderers/CSS2DRenderer.js';
import URDFLoader from 'urdf-loader';
import { getBinary } from './api.js';

const OBJECT_COLOURS = { table: 0x8a7356 };

export class CellView {
  constructor(container) {
    this.container = container;
    this.renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
    this.renderer.setClearColor(0xf2f4f7);
    container.appendChild(this.renderer.domElement);
    // Frame labels: HTML over the canvas, placed by the same camera.
    this.labelRenderer = new CSS2DRenderer();
    this.labelRenderer.domElement.className = 'frame-labels';
    container.appendChild(this.labelRenderer.domElement);
    this.scene = new THREE.Scene();
    this.root = new THREE.Group();
    this.root.rotation.x = -Math.PI / 2; // z-up to y-up
    this.scene.add(this.root);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x667788, 2.2));
    const sun = new THREE.DirectionalLight(0xffffff, 1.6);
    sun.position.set(1.5, 3, 2);
    this.scene.add(sun);
    const grid = new THREE.GridHelper(2, 20, 0xb0b8c4, 0xd4d9e0);
    this.scene.add(grid);
    this.camera = new THREE.PerspectiveCamera(40, 1, 0.01, 50);
    this.camera.position.set(0.9, 1.5, 1.5);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.target.set(0, 0.8, 0);
    this.controls.update();
    this.controls.addEventListener('change', () => this.render());
    this.controls.addEventListener('start', () => { this.userMoved = true; });
    this.userMoved = false;
    this.collision = null;       // the planner's geometry, drawn under each link
    this.showCollision = false;
    this.labels = [];
    this.showLabels = false;
    this.robot = null;
    this.objects = new Map();
    this.frames = [];
    this.showFrames = false;
    this.onFirstFrame = null;
    this._pending = false;
    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
  }

  resize() {
    const w = this.container.clientWidth || 640;
    const h = this.container.clientHeight || 480;
    this.renderer.setSize(w, h, false);
    this.labelRenderer.setSize(w, h);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.render();
  }

  render() {
    if (this._pending) return;
    this._pending = true;
    requestAnimationFrame(() => {
      this._pending = false;
      this.renderer.render(this.scene, this.camera);
      this.labelRenderer.render(this.scene, this.camera);
      if (this.robot && this.onFirstFrame) {
        const cb = this.onFirstFrame;
        this.onFirstFrame = null;
        cb();
      }
    });
  }

  // Load a cell description (GET /viewer/cells/{id}); returns once the URDF is parsed
  // (primitives drawn; meshes arrive afterwards and redraw).
  loadCell(cell) {
    this.clear();
    this.cell = cell;
    const manager = new THREE.LoadingManager();
    // Meshes in: fit the view to the robots as drawn, unless the user has moved it.
    manager.onLoad = () => { if (!this.userMoved) this.fitView(); this.render(); };
    this.userMoved = false;
    const loader = new URDFLoader(manager);
    loader.workingPath = '/viewer/';
    loader.loadMeshCb = (path, mgr, done) => loadMesh(path, mgr, done, () => this.render());
    this.robot = loader.parse(cell.urdf);
    this.robot.traverse((o) => { if (o.isMesh) { o.castShadow = false; } });
    this.root.add(this.robot);
    for (const [name, value] of Object.entries(cell.start || {})) this.setJoint(name, value);
    this.setObjects(cell.objects || []);
    this.buildFrames();
    this.buildLabels();
    this.frameRobots();  // the viewing direction, then the robots' box fitted
    this.fitView();
  }

  // Fit the view to the robots' bounding box (their drawn links, the meshes once
  // loaded; the links that hang below the world's fixed joints, not a floor or table of
  // the merged URDF), from the current viewing direction.
  fitView() {
    if (!this.robot) return;
    this.scene.updateMatrixWorld(true);
    const box = this.robotBox();
    if (box.isEmpty()) { this.frameRobots(); return; }
    const sphere = box.getBoundingSphere(new THREE.Sphere());
    const radius = Math.max(sphere.radius, 0.05);
    const fov = THREE.MathUtils.degToRad(this.camera.fov);
    const fit = Math.min(fov, 2 * Math.atan(Math.tan(fov / 2) * this.camera.aspect));
    const distance = (1.3 * radius) / Math.sin(fit / 2);
    const dir = this.camera.position.clone().sub(this.controls.target);
    if (dir.lengthSq() < 1e-9) dir.set(0.35, 0.55, 1);
    dir.normalize();
    this.controls.target.copy(sphere.center);
    this.camera.position.copy(sphere.center).addScaledVector(dir, distance);
    this.controls.minDistance = radius * 0.2;
    this.controls.maxDistance = radius * 20;
    this.camera.near = Math.max(0.001, distance / 100);
    this.camera.far = distance * 50;
    this.camera.updateProjectionMatrix();
    this.controls.update();
    this.render();
  }

  // The box of every link of a robot (from the link each first moving joint hangs on,
  // down): visuals where they are loaded, link origins always.
  robotBox() {
    const box = new THREE.Box3();
    const at = new THREE.Vector3();
    const seen = new Set();
    const add = (link) => {
      if (seen.has(link)) return;
      seen.add(link);
      box.expandByPoint(link.getWorldPosition(at));
      for (const child of link.children) {
        if (child.isURDFVisual) box.expandByObject(child);
      }
    };
    for (const joint of Object.values(this.robot.joints)) {
      if (joint.jointType === 'fixed') continue;
      if (joint.parent && joint.parent.isURDFLink) add(joint.parent);
      joint.traverse((o) => { if (o.isURDFLink) add(o); });
    }
    return box;
  }

  // The planner's collision geometry (GET /viewer/cells/{id}/collision): each shape
  // under its link, translucent, drawn when the toggle is on.
  setCollision(data) {
    if (this.collision) for (const g of this.collision) g.removeFromParent();
    this.collision = [];
    if (!this.robot || !data) return;
    const material = new THREE.MeshStandardMaterial({ color: 0xe0702a, transparent: true, opacity: 0.45,
      depthWrite: false, roughness: 0.8 });
    for (const entry of data.links) {
      const link = this.robot.links[entry.link];
      if (!link) continue;
      for (const spec of entry.shapes) {
        const mesh = collisionMesh(spec, material);
        if (!mesh) continue;
        const holder = new THREE.Group();
        holder.name = 'collision:' + entry.link;
        holder.userData.kind = entry.kind;
        holder.position.set(...spec.pose.xyz);
        holder.quaternion.set(...spec.pose.quat);
        holder.add(mesh);
        holder.visible = this.showCollision;
        link.add(holder);
        this.collision.push(holder);
      }
    }
    this.render();
  }

  setCollisionVisible(on) {
    this.showCollision = on;
    for (const g of this.collision || []) g.visible = on;
    this.render();
  }

  // Labelled frames: each group's tool frame and each robot's base (the links under the
  // world), bigger axes and their names.
  buildLabels() {
    for (const l of this.labels) l.removeFromParent();
    this.labels = [];
    if (!this.robot || !this.cell) return;
    const named = new Map();
    for (const joint of Object.values(this.robot.joints)) {
      if (joint.parent !== this.robot) continue;
      for (const child of joint.children) if (child.isURDFLink) named.set(child.urdfName, 'base');
    }
    for (const group of this.cell.groups || []) {
      if (group.tip_link) named.set(group.tip_link, `tool (${group.name})`);
    }
    for (const [name, role] of named) {
      const link = this.robot.links[name];
      if (!link) continue;
      const holder = new THREE.Group();
      holder.name = 'label:' + name;
      holder.add(new THREE.AxesHelper(0.08));
      const text = document.createElement('div');
      text.className = 'frame-label';
      text.textContent = `${name} · ${role}`;
      const tag = new CSS2DObject(text);
      tag.position.set(0, 0, 0.02);
      holder.add(tag);
      holder.visible = this.showLabels;
      holder.traverse((o) => { o.visible = this.showLabels; });
      link.add(holder);
      this.labels.push(holder);
    }
  }

  setLabels(on) {
    this.showLabels = on;
    for (const l of this.labels) l.traverse((o) => { o.visible = on; });
    this.render();
  }

  // Aim the camera at the robots: the orbit's centre is the middle of the links that
  // move (from the link each first moving joint hangs on, down to the tool), not of the
  // table under them or of the floor the merged URDF's world link sits on, so that the
  // wheel zooms in on the arms. Link origins, not meshes: meshes load later.
  frameRobots() {
    this.scene.updateMatrixWorld(true);
    const box = new THREE.Box3();
    const at = new THREE.Vector3();
    for (const joint of Object.values(this.robot.joints)) {
      if (joint.jointType === 'fixed') continue;
      if (joint.parent && joint.parent.isURDFLink) box.expandByPoint(joint.parent.getWorldPosition(at));
      joint.traverse((o) => { if (o.isURDFLink) box.expandByPoint(o.getWorldPosition(at)); });
    }
    if (box.isEmpty()) box.setFromObject(this.robot);
    if (box.isEmpty()) return;
    const centre = box.getCenter(new THREE.Vector3());
    const size = Math.max(0.35, 1.2 * box.getSize(new THREE.Vector3()).length() + 0.1);
    this.controls.target.copy(centre);
    const dir = new THREE.Vector3(0.35, 0.55, 1).normalize();
    this.camera.position.copy(centre).addScaledVector(dir, size * 1.6);
    this.controls.minDistance = size * 0.2;
    this.controls.maxDistance = size * 10;
    this.camera.near = size / 100;
    this.camera.far = size * 50;
    this.camera.updateProjectionMatrix();
    this.controls.update();
  }

  // Where a link is drawn: normalised device coordinates (x, y in -1..1 on the canvas).
  onScreen(linkName) {
    const link = this.robot && this.robot.links[linkName];
    if (!link) return null;
    this.scene.updateMatrixWorld(true);
    const v = link.getWorldPosition(new THREE.Vector3()).project(this.camera);
    return [v.x, v.y, v.z];
  }

  clear() {
    if (this.robot) this.root.remove(this.robot);
    for (const l of this.labels) l.traverse((o) => { if (o.element) o.element.remove(); });
    this.labels = [];
    this.collision = null;
    for (const obj of this.objects.values()) obj.removeFromParent();
    this.objects.clear();
    this.frames = [];
    this.robot = null;
  }

  setJoint(name, value) {
    const joint = this.robot && this.robot.joints[name];
    if (joint && joint.jointType !== 'fixed') joint.setJointValue(value);
  }

  setJoints(values) {
    for (const [name, value] of Object.entries(values)) this.setJoint(name, value);
    this.render();
  }

  jointValue(name) {
    const joint = this.robot && this.robot.joints[name];
    return joint ? Number(joint.angle) : 0;
  }

  // Objects as a scene lists them: world objects under the root, attached ones under
  // the link that carries them (so they move with it).
  setObjects(objects) {
    const seen = new Set();
    for (const spec of objects) {
      seen.add(spec.name);
      let obj = this.objects.get(spec.name);
      const key = JSON.stringify(spec.shape);
      if (!obj || obj.userData.key !== key) {
        if (obj) obj.removeFromParent();
        obj = makeObject(spec);
        obj.userData.key = key;
        this.objects.set(spec.name, obj);
      }
      const parent = spec.attached_to && this.robot ? this.robot.links[spec.attached_to] : null;
      (parent || this.root).add(obj);
      obj.position.set(...spec.pose.xyz);
      obj.quaternion.set(...spec.pose.quat);
      obj.userData.attachedTo = spec.attached_to || null;
      const held = spec.attached_to || spec.held;  // held: measured by physics, in the world
      obj.children.forEach((c) => { if (c.material) c.material.emissive?.setHex(held ? 0x223355 : 0); });
    }
    for (const [name, obj] of this.objects) {
      if (!seen.has(name)) { obj.removeFromParent(); this.objects.delete(name); }
    }
    this.render();
  }

  // A world position of an object (for tests and the replay's readout).
  objectWorld(name) {
    const obj = this.objects.get(name);
    if (!obj) return null;
    const v = new THREE.Vector3();
    obj.getWorldPosition(v);
    // back to the robot's z-up frame
    return [v.x, -v.z, v.y];
  }

  buildFrames() {
    for (const f of this.frames) f.removeFromParent();
    this.frames = [];
    if (!this.robot) return;
    for (const [name, link] of Object.entries(this.robot.links)) {
      const axes = new THREE.AxesHelper(0.04);
      axes.name = 'frame:' + name;
      axes.visible = this.showFrames;
      link.add(axes);
      this.frames.push(axes);
    }
  }

  setFrames(on) {
    this.showFrames = on;
    for (const f of this.frames) f.visible = on;
    this.render();
  }
}

function makeObject(spec) {
  const shape = spec.shape;
  let geometry;
  if (shape.type === 'box') geometry = new THREE.BoxGeometry(...shape.size);
  else if (shape.type === 'sphere') geometry = new THREE.SphereGeometry(shape.radius, 24, 16);
  else if (shape.type === 'cylinder') {
    geometry = new THREE.CylinderGeometry(shape.radius, shape.radius, shape.length, 32);
    geometry.rotateX(Math.PI / 2); // URDF cylinders run along z
  } else geometry = new THREE.SphereGeometry(0.02, 12, 8); // a mesh object: a marker
  const colour = OBJECT_COLOURS[spec.name] ?? 0x3a7bd5;
  const material = new THREE.MeshStandardMaterial({ color: colour, roughness: 0.7, metalness: 0.05 });
  const mesh = new THREE.Mesh(geometry, material);
  const group = new THREE.Group();
  group.name = 'object:' + spec.name;
  group.add(mesh);
  return group;
}

// A shape of the collision geometry as a three.js mesh (cylinders and capsules along z).
function collisionMesh(spec, material) {
  let geometry;
  if (spec.type === 'box') {
    geometry = new THREE.BoxGeometry(...spec.size);
    if (spec.centre) geometry.translate(...spec.centre);
  } else if (spec.type === 'sphere') geometry = new THREE.SphereGeometry(spec.radius, 20, 14);
  else if (spec.type === 'cylinder' || spec.type === 'capsule') {
    geometry = spec.type === 'cylinder' ? new THREE.CylinderGeometry(spec.radius, spec.radius, spec.length, 24)
      : new THREE.CapsuleGeometry(spec.radius, spec.length, 6, 16);
    geometry.rotateX(Math.PI / 2);
  } else if (spec.type === 'hull') {
    const points = [];
    for (let i = 0; i + 2 < spec.points.length; i += 3) points.push(new THREE.Vector3(spec.points[i], spec.points[i + 1], spec.points[i + 2]));
    if (points.length < 4) return null;
    geometry = new ConvexGeometry(points);
  } else if (spec.type === 'mesh') {
    geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.Float32BufferAttribute(spec.vertices, 3));
    geometry.setIndex(spec.triangles);
    geometry.computeVertexNormals();
  } else return null;
  const mesh = new THREE.Mesh(geometry, material);
  mesh.renderOrder = 2;
  return mesh;
}

export function loadMesh(path, manager, done, redraw) {
  const ext = path.split('?')[0].split('.').pop().toLowerCase();
  manager.itemStart(path);
  getBinary(path).then((buffer) => {
    let object;
    if (ext === 'stl') {
      const geometry = new STLLoader().parse(buffer);
      object = new THREE.Mesh(geometry, new THREE.MeshStandardMaterial({ color: 0xcccccc }));
    } else if (ext === 'dae') {
      const text = new TextDecoder().decode(buffer);
      object = new ColladaLoader(manager).parse(text, path.slice(0, path.lastIndexOf('/') + 1)).scene;
    } else if (ext === 'obj') {
      object = new OBJLoader(manager).parse(new TextDecoder().decode(buffer));
    } else {
      throw new Error('unsupported mesh type: ' + path);
    }
    done(object);
    redraw();
  }).catch((err) => {
    console.warn('mesh not loaded:', path, err.message);
    done(null, err);
  }).finally(() => manager.itemEnd(path));
}
