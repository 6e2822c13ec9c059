// The goal state in 3D, as RViz's MotionPlanning display draws it: a ghost of the robot
// at the goal (green when the planner can go there, red when not), a handle on the
// planning group's tool frame (three.js TransformControls: drag to move, or turn), the
// planned trajectory's end-effector trail, and the ghost playing the trajectory.
// The handle lives under the stage's z-up root, so its position and quaternion are
// world coordinates of the cell (m; x, y, z, w) as the server's IK takes them.

import * as THREE from 'three';
import { TransformControls } from 'three/examples/jsm/controls/TransformControls.js';
import URDFLoader from 'urdf-loader';
import { loadMesh } from './scene3d.js';

const OK_COLOUR = 0x2fb56a;
const BAD_COLOUR = 0xd83a3a;

export class GoalView {
  constructor(stage) {
    this.stage = stage;
    this.material = new THREE.MeshStandardMaterial({
      color: OK_COLOUR, transparent: true, opacity: 0.45, depthWrite: false, roughness: 0.8,
    });
    this.ghost = null;
    this.cellId = null;
    this.tip = null;
    this.target = new THREE.Object3D();
    this.target.name = 'goal-target';
    this.handle = new TransformControls(stage.camera, stage.renderer.domElement);
    this.handle.setSize(0.8);
    this.handle.addEventListener('change', () => stage.render());
    this.handle.addEventListener('dragging-changed', (e) => {
      stage.controls.enabled = !e.value;
      this.dragging = e.value;
      if (!e.value && this.onDragEnd) this.onDragEnd();
    });
    this.handle.addEventListener('objectChange', () => { if (this.onDrag) this.onDrag(this.pose()); });
    // a second handle for the obstacle being moved (translate and turn)
    this.objectHandle = new TransformControls(stage.camera, stage.renderer.domElement);
    this.objectHandle.setSize(0.6);
    this.objectHandle.addEventListener('change', () => stage.render());
    this.objectHandle.addEventListener('dragging-changed', (e) => {
      stage.controls.enabled = !e.value;
      this.movingObject = e.value;
    });
    this.objectHandle.addEventListener('objectChange', () => {
      const o = this.objectHandle.object;
      if (o && this.onObjectMoved) {
        this.onObjectMoved(o.name.replace(/^object:/, ''), [o.position.x, o.position.y, o.position.z],
          [o.quaternion.x, o.quaternion.y, o.quaternion.z, o.quaternion.w]);
      }
    });
    this.movingObject = false;
    this.onObjectMoved = null;
    this.dragging = false;
    this.onDrag = null;
    this.onDragEnd = null;
    this.trail = null;
    this.playing = null;
  }

  // A ghost of the cell's robots (its own copy of the URDF, meshes painted translucent).
  load(cell) {
    if (this.cellId === cell.id && this.ghost) return;
    this.unload();
    this.cellId = cell.id;
    const loader = new URDFLoader(new THREE.LoadingManager());
    loader.workingPath = '/viewer/';
    loader.loadMeshCb = (path, mgr, done) => loadMesh(path, mgr, (obj, err) => {
      if (obj) this.paint(obj);
      done(obj, err);
    }, () => this.stage.render());
    this.ghost = loader.parse(cell.urdf);
    this.ghost.name = 'goal-ghost';
    this.paint(this.ghost);
    this.stage.root.add(this.ghost);
    this.stage.root.add(this.target);
    this.stage.scene.add(this.handle.getHelper());
    this.stage.scene.add(this.objectHandle.getHelper());
  }

  // Put the obstacle handle on an object of the stage (null: none).
  moveObject(name) {
    const obj = name ? this.stage.objects.get(name) : null;
    if (obj) this.objectHandle.attach(obj); else this.objectHandle.detach();
    this.stage.render();
  }

  unload() {
    this.handle.detach();
    this.objectHandle.detach();
    this.objectHandle.getHelper().removeFromParent();
    this.handle.getHelper().removeFromParent();
    this.target.removeFromParent();
    if (this.ghost) this.ghost.removeFromParent();
    this.clearTrail();
    this.ghost = null;
    this.cellId = null;
  }

  paint(object) {
    object.traverse((o) => { if (o.isMesh) { o.material = this.material; o.renderOrder = 2; } });
  }

  setVisible(on) {
    if (this.ghost) this.ghost.visible = on;
    this.handle.getHelper().visible = on && Boolean(this.tip);
    if (this.trail) this.trail.visible = on;
    this.handle.enabled = on && Boolean(this.tip);
    if (!on) this.objectHandle.detach();
    this.stage.render();
  }

  // Which link the handle moves (null: the group has no tip link; no handle).
  setTip(link) {
    this.tip = link && this.ghost && this.ghost.links[link] ? link : null;
    if (this.tip) this.handle.attach(this.target); else this.handle.detach();
    this.handle.getHelper().visible = Boolean(this.tip);
    this.handle.enabled = Boolean(this.tip);
    this.stage.render();
  }

  setMode(mode) { this.handle.setMode(mode); }

  setJoints(values) {
    if (!this.ghost) return;
    for (const [name, value] of Object.entries(values)) {
      const joint = this.ghost.joints[name];
      if (joint && joint.jointType !== 'fixed') joint.setJointValue(value);
    }
    this.stage.render();
  }

  jointValue(name) {
    const joint = this.ghost && this.ghost.joints[name];
    return joint ? Number(joint.angle) : 0;
  }

  setOk(ok) {
    this.material.color.setHex(ok ? OK_COLOUR : BAD_COLOUR);
    this.ok = ok;
    this.stage.render();
  }

  // Put the handle on a world pose (m; quaternion x, y, z, w), unless it is being dragged.
  placeHandle(xyz, quat) {
    if (this.dragging) return;
    this.target.position.set(...xyz);
    this.target.quaternion.set(...quat);
    this.stage.render();
  }

  // The handle's world pose.
  pose() {
    const p = this.target.position, q = this.target.quaternion;
    return { xyz: [p.x, p.y, p.z], quat: [q.x, q.y, q.z, q.w] };
  }

  // Where the handle is drawn: normalised device coordinates (for tests and hints).
  handleOnScreen() {
    this.stage.scene.updateMatrixWorld(true);
    const v = this.target.getWorldPosition(new THREE.Vector3()).project(this.stage.camera);
    return [v.x, v.y, v.z];
  }

  clearTrail() {
    if (this.trail) { this.trail.removeFromParent(); this.trail.geometry.dispose(); }
    this.trail = null;
    if (this.playing) cancelAnimationFrame(this.playing);
    this.playing = null;
  }

  // The tool's path along a planned trajectory (times, positions of joint_names) as a
  // line, then the ghost playing the trajectory once in real time; it rests at the goal.
  showTrajectory(plan, restAt) {
    this.clearTrail();
    if (!this.ghost || !plan.times.length) return;
    const names = plan.joint_names;
    const at = (row) => Object.fromEntries(names.map((n, i) => [n, row[i]]));
    const link = this.ghost.links[this.tip || ''];
    if (link) {
      const step = Math.max(1, Math.floor(plan.positions.length / 300));
      const points = [];
      const v = new THREE.Vector3();
      for (let k = 0; k < plan.positions.length; k += step) {
        this.setJoints(at(plan.positions[k]));
        this.stage.root.updateMatrixWorld(true);
        points.push(this.stage.root.worldToLocal(link.getWorldPosition(v)).clone());
      }
      this.setJoints(at(plan.positions[plan.positions.length - 1]));
      this.stage.root.updateMatrixWorld(true);
      points.push(this.stage.root.worldToLocal(link.getWorldPosition(v)).clone());
      const geometry = new THREE.BufferGeometry().setFromPoints(points);
      this.trail = new THREE.Line(geometry, new THREE.LineBasicMaterial({ color: 0xe08a00 }));
      this.trail.name = 'goal-trail';
      this.trail.renderOrder = 3;
      this.stage.root.add(this.trail);
    }
    const duration = plan.times[plan.times.length - 1];
    const began = performance.now();
    let k = 0;
    const frame = (now) => {
      const t = (now - began) / 1000;
      while (k + 1 < plan.times.length && plan.times[k + 1] <= t) k++;
      this.setJoints(at(plan.positions[k]));
      if (t < duration) this.playing = requestAnimationFrame(frame);
      else { this.playing = null; this.setJoints(restAt); }
    };
    this.playing = requestAnimationFrame(frame);
  }
}
