// Plan and execute from the page (the Cell view), as RViz's MotionPlanning panel does:
// pick a planning group, set its goal by dragging the tool frame (solved by IK on the
// server as it moves), by the joint sliders or by a named pose; Plan (POST /plan: the
// trajectory plays on the goal ghost and leaves the tool's trail); Execute (a run on
// the server's backend, token needed) and Stop (the run's cancel). The robot drawn
// solid is where the backend says it is; the ghost is the goal.

import { get, post, request } from './api.js';

const POLL_MS = 120;
const SESSION_OBSTACLES = new Map(); // cell id -> the obstacles added on this page
const JOG_RAD = 0.05;   // a jog step of a revolute joint (rad)
const JOG_M = 0.005;    // of a prismatic one (m)

export class PlanPanel {
  // ui: { el, guarded, side }; debug: the page's window.__viewer
  constructor(ui, stage, goal, cell, debug) {
    this.ui = ui;
    this.stage = stage;
    this.goal = goal;
    this.cell = cell;
    this.debug = debug;
    this.groups = cell.groups.filter((g) => g.joints.some((j) => this.movable(j)));
    this.group = (this.groups.find((g) => g.tip_link && /arm/.test(g.name))
      || this.groups.find((g) => g.tip_link) || this.groups[0] || null);
    this.backend = 'sim';
    this.mode = 'pose';
    this.robot = {};       // joint values the backend reports
    this.goalJoints = {};  // the ghost's joint values (the goal state)
    this.answer = null;    // the server's last word on the goal
    this.plan = null;
    this.run = null;       // { id, status } of an Execute
    this.inflight = false;
    this.pending = null;
    this.timer = null;
    this.closed = false;
    if (!SESSION_OBSTACLES.has(cell.id)) SESSION_OBSTACLES.set(cell.id, []);
    this.obstacles = SESSION_OBSTACLES.get(cell.id);
    this.info = { state: this, answers: 0, obstacles: this.obstacles };
    debug.plan = this.info;
  }

  movable(name) {
    const joint = this.cell.joints.find((j) => j.name === name);
    return joint && !joint.mimic && !joint.passive && joint.type !== 'fixed';
  }

  close() {
    this.closed = true;
    clearTimeout(this.timer);
    this.goal.onObjectMoved = null;
    this.goal.moveObject(null);
    this.goal.onDrag = null;
    this.goal.onDragEnd = null;
    this.goal.setVisible(false);
  }

  async build() {
    const { el, side } = this.ui;
    if (!this.group) return;
    const groupSelect = el('select', { id: 'plan-group' },
      ...this.groups.map((g) => el('option', { value: g.name, textContent: g.name, selected: g === this.group })));
    groupSelect.addEventListener('change', () => this.selectGroup(groupSelect.value));
    const backend = el('select', { id: 'plan-backend' },
      ...['sim', 'mock'].map((b) => el('option', { value: b, textContent: b })));
    backend.addEventListener('change', () => this.ui.guarded(async () => {
      this.backend = backend.value;
      this.plan = null;
      await this.readState(true);
      this.refresh();
    }));
    const mode = el('select', { id: 'plan-mode' },
      el('option', { value: 'pose', textContent: 'drag the tool frame (IK)' }),
      el('option', { value: 'turn', textContent: 'turn the tool frame (IK)' }),
      el('option', { value: 'joints', textContent: 'joint sliders' }));
    mode.addEventListener('change', () => {
      this.mode = mode.value;
      this.goal.setMode(mode.value === 'turn' ? 'rotate' : 'translate');
      this.goal.handle.enabled = mode.value !== 'joints' && Boolean(this.goal.tip);
    });
    this.scaling = el('input', { id: 'plan-scaling', type: 'number', min: '0.05', max: '1', step: '0.05', value: '0.5', style: 'width:5em' });
    this.planButton = el('button', { id: 'plan-plan', type: 'button', textContent: 'Plan' });
    this.executeButton = el('button', { id: 'plan-execute', type: 'button', textContent: 'Execute', disabled: true });
    this.stopButton = el('button', { id: 'plan-stop', type: 'button', textContent: 'Stop', disabled: true });
    const toCurrent = el('button', { type: 'button', textContent: 'goal = current' });
    this.planButton.addEventListener('click', () => this.ui.guarded(() => this.doPlan()));
    this.executeButton.addEventListener('click', () => this.ui.guarded(() => this.doExecute()));
    this.stopButton.addEventListener('click', () => this.ui.guarded(() => this.doStop()));
    toCurrent.addEventListener('click', () => { this.setGoal(this.groupValues(this.robot)); });
    this.status = el('div', { id: 'plan-status', className: 'banner', textContent: 'goal: reading the robot…' });
    this.runLine = el('a', { id: 'plan-run', hidden: true });
    this.slidersBox = el('div', { id: 'plan-sliders' });
    side.append(el('h2', { textContent: 'Plan and execute' }),
      el('label', { className: 'row' }, 'group ', groupSelect, ' backend ', backend),
      el('label', { className: 'row' }, 'goal ', mode),
      el('label', { className: 'row' }, 'velocity scaling ', this.scaling),
      el('div', { className: 'row-ctl' }, this.planButton, this.executeButton, this.stopButton, toCurrent),
      this.status, this.runLine);
    side.append(el('h2', { textContent: 'Named poses (as goals)' }));
    this.poseSelects = new Map();
    for (const group of this.cell.groups) {
      const names = Object.keys(group.poses);
      if (!this.groups.includes(group)) continue;
      const select = el('select', { name: 'pose:' + group.name },
        el('option', { value: '', textContent: '—' }), ...names.map((n) => el('option', { value: n, textContent: n })));
      this.poseSelects.set(group.name, select);
      select.addEventListener('change', () => {
        if (!select.value) return;
        if (group !== this.group) { groupSelect.value = group.name; this.selectGroup(group.name); }
        this.setGoal(group.poses[select.value]);
      });
      side.append(el('label', { className: 'row' }, el('span', { textContent: group.name }), select));
    }
    const teachName = el('input', { id: 'teach-name', placeholder: 'pose name', size: 12 });
    const teach = el('button', { id: 'teach', type: 'button', textContent: 'teach the robot\'s state' });
    teach.addEventListener('click', () => this.ui.guarded(() => this.doTeach(teachName.value.trim())));
    side.append(el('div', { className: 'row-ctl' }, teachName, teach));
    side.append(el('h2', { textContent: 'Goal joints (the sliders set the goal, not the robot; ± jogs the robot)' }), this.slidersBox);
    this.obstacleBox = el('div', { id: 'obstacles' });
    const adders = ['box', 'cylinder', 'sphere'].map((shape) => {
      const b = el('button', { type: 'button', textContent: `+ ${shape}` });
      b.dataset.add = shape;
      b.addEventListener('click', () => this.addObstacle(shape));
      return b;
    });
    side.append(el('h2', { textContent: 'Obstacles (this page only; planned around, sent with Execute)' }),
      el('div', { className: 'row-ctl' }, ...adders), this.obstacleBox);
    this.goal.onObjectMoved = (name, xyz, quat) => {
      const o = this.obstacles.find((x) => x.name === name);
      if (!o) return;
      o.xyz = xyz;
      o.quat = quat;
      this.obstaclesChanged(false);
    };
    this.drawObstacles();
    this.goal.onDrag = (pose) => { if (this.mode !== 'joints') this.ask({ pose }); };
    this.goal.setVisible(true);
    await this.readState(true);
    this.selectGroup(this.group.name);
  }

  // ------------------------------------------------------------ obstacles
  addObstacle(shape) {
    let k = this.obstacles.length + 1;
    while (this.obstacles.some((o) => o.name === `${shape}_${k}`)) k++;
    const at = this.answer ? this.answer.xyz : [0.3, 0, 1];
    const o = { name: `${shape}_${k}`, shape, xyz: [at[0], at[1] + 0.12, at[2]], quat: [0, 0, 0, 1] };
    if (shape === 'box') o.size = [0.05, 0.05, 0.05];
    else if (shape === 'cylinder') { o.radius = 0.025; o.length = 0.1; } else o.radius = 0.03;
    this.obstacles.push(o);
    this.selected = o.name;
    this.obstaclesChanged(true);
  }

  obstaclesChanged(rebuild) {
    this.drawObstacles(rebuild);
    this.plan = null;
    this.goal.clearTrail();
    this.ask({ joints: this.groupValues(this.goalJoints) });
  }

  sceneObjects() {
    const shapeOf = (o) => (o.shape === 'box' ? { type: 'box', size: o.size }
      : o.shape === 'cylinder' ? { type: 'cylinder', radius: o.radius, length: o.length }
        : { type: 'sphere', radius: o.radius });
    return [...this.cell.objects,
      ...this.obstacles.map((o) => ({ name: o.name, shape: shapeOf(o), pose: { xyz: o.xyz, quat: o.quat } }))];
  }

  drawObstacles(rebuild = true) {
    if (!this.goal.movingObject) this.stage.setObjects(this.sceneObjects());
    if (!rebuild) return;
    const { el } = this.ui;
    this.obstacleBox.textContent = '';
    for (const o of this.obstacles) {
      const dims = o.shape === 'box' ? o.size.map((v, i) => ['x', 'y', 'z'][i] + ' ' + v)
        : o.shape === 'cylinder' ? [`r ${o.radius}`, `length ${o.length}`] : [`r ${o.radius}`];
      const size = el('input', { value: dims.join(', '), size: 16, title: 'm' });
      size.addEventListener('change', () => {
        const numbers = (size.value.match(/[0-9.]+(e-?[0-9]+)?/g) || []).map(Number);
        if (o.shape === 'box' && numbers.length === 3) o.size = numbers;
        else if (o.shape === 'cylinder' && numbers.length === 2) [o.radius, o.length] = numbers;
        else if (o.shape === 'sphere' && numbers.length === 1) [o.radius] = numbers;
        this.obstaclesChanged(true);
      });
      const move = el('input', { type: 'radio', name: 'obstacle-move', checked: this.selected === o.name, title: 'move it with the handle' });
      move.addEventListener('change', () => { this.selected = o.name; this.goal.moveObject(o.name); });
      const remove = el('button', { type: 'button', textContent: '✕', title: 'remove' });
      remove.addEventListener('click', () => {
        this.obstacles.splice(this.obstacles.indexOf(o), 1);
        if (this.selected === o.name) this.selected = null;
        this.obstaclesChanged(true);
      });
      this.obstacleBox.append(el('label', { className: 'row obstacle' }, move, el('span', { textContent: o.name }), size, remove));
    }
    this.goal.moveObject(this.obstacles.some((o) => o.name === this.selected) ? this.selected : null);
  }

  groupValues(values) {
    return Object.fromEntries(this.group.joints.filter((j) => this.movable(j) && j in values)
      .map((j) => [j, values[j]]));
  }

  selectGroup(name) {
    this.group = this.groups.find((g) => g.name === name) || this.group;
    this.plan = null;
    this.goal.clearTrail();
    this.goal.setTip(this.group.tip_link);
    this.goal.handle.enabled = this.mode !== 'joints' && Boolean(this.goal.tip);
    this.buildSliders();
    this.setGoal(this.groupValues(this.goalJoints));
  }

  buildSliders() {
    const { el } = this.ui;
    this.slidersBox.textContent = '';
    this.sliders = new Map();
    for (const name of this.group.joints) {
      if (!this.movable(name)) continue;
      const joint = this.cell.joints.find((j) => j.name === name);
      const lo = joint.lower ?? -Math.PI, hi = joint.upper ?? Math.PI;
      const input = el('input', { type: 'range', min: lo, max: hi, step: (hi - lo) / 1000, value: this.goalJoints[name] ?? 0 });
      input.dataset.joint = name;
      const readout = el('span', { className: 'goal-value' });
      const now = el('span', { className: 'robot-value', title: 'where the robot is' });
      input.sync = () => {
        input.value = this.goalJoints[name] ?? 0;
        readout.textContent = Number(this.goalJoints[name] ?? 0).toFixed(3);
        now.textContent = Number(this.robot[name] ?? 0).toFixed(3);
      };
      input.addEventListener('input', () => {
        this.setGoal({ [name]: Number(input.value) });
      });
      const step = joint.type === 'prismatic' ? JOG_M : JOG_RAD;
      const jog = (sign) => {
        const b = el('button', { type: 'button', className: 'jog', textContent: sign > 0 ? '+' : '−', title: `jog ${name} by ${sign * step}` });
        b.dataset.jog = `${name}:${sign}`;
        b.addEventListener('click', (ev) => { ev.preventDefault(); this.ui.guarded(() => this.doJog(name, sign * step, lo, hi)); });
        return b;
      };
      this.sliders.set(name, input);
      this.slidersBox.append(el('label', { className: 'slider goal' }, el('span', { textContent: name, title: name }), input, readout, now, jog(-1), jog(1)));
      input.sync();
    }
  }

  syncSliders() {
    for (const input of (this.sliders || new Map()).values()) input.sync();
  }

  // The goal set to joint values (a slider, a named pose): drawn at once, checked by
  // the server (limits, collisions, the tool's pose for the handle).
  setGoal(values) {
    Object.assign(this.goalJoints, values);
    this.goal.setJoints(this.goalJoints);
    this.plan = null;
    this.goal.clearTrail();
    this.syncSliders();
    this.refresh();
    this.ask({ joints: this.groupValues(this.goalJoints) });
  }

  // Ask the server about the goal: one request in flight, the newest waiting behind it
  // (a drag sends no more than the server answers).
  ask(goal) {
    this.pending = goal;
    if (this.inflight) return;
    clearTimeout(this.timer);
    this.timer = setTimeout(() => this.sendPending(), 40);
  }

  async sendPending() {
    if (this.closed || !this.pending) return;
    const goal = this.pending;
    this.pending = null;
    this.inflight = true;
    const body = { group: this.group.name, seed: this.groupValues(this.goalJoints), obstacles: this.obstacles };
    if (goal.pose) body.pose = { xyz: goal.pose.xyz, quat: goal.pose.quat, link: this.goal.tip };
    else body.joints = goal.joints;
    try {
      const answer = await post(`/viewer/cells/${encodeURIComponent(this.cell.id)}/goal`, body);
      if (this.closed) return;
      this.answer = answer;
      this.info.answers += 1;
      this.info.answer = answer;
      Object.assign(this.goalJoints, answer.joints);
      this.goal.setJoints(this.goalJoints);
      this.goal.setOk(answer.ok);
      if (!goal.pose || !this.goal.dragging) {
        if (goal.joints) this.goal.placeHandle(answer.xyz, answer.quat);
      }
      this.plan = null;
      this.goal.clearTrail();
      this.syncSliders();
      this.refresh();
    } catch (err) {
      this.status.textContent = `goal: ${err.message}`;
      this.status.className = 'banner status-failed';
    } finally {
      this.inflight = false;
      if (this.pending) this.sendPending();
    }
  }

  refresh() {
    const running = this.run && this.run.status === 'running';
    const ok = this.answer ? this.answer.ok : false;
    this.planButton.disabled = running || !ok;
    this.executeButton.disabled = running || !this.plan;
    this.stopButton.disabled = !running;
    let text, cls;
    if (running) { text = `executing on ${this.backend} (run ${this.run.id})…`; cls = 'status-running'; }
    else if (!this.answer) { text = 'goal: checking…'; cls = ''; }
    else if (!this.answer.ok) { text = `goal: ${this.answer.reason}`; cls = 'status-failed'; }
    else if (this.plan) {
      text = `planned: ${this.plan.duration.toFixed(2)} s of motion, found in ${(1000 * this.plan.planning_time).toFixed(0)} ms; Execute runs it on ${this.backend}`;
      cls = 'status-succeeded';
    } else { text = 'goal: reachable and collision-free; press Plan'; cls = 'status-succeeded'; }
    this.status.textContent = text;
    this.status.className = `banner ${cls}`;
    this.info.status = text;
    const run = this.run && this.run.done ? this.run : null;
    this.runLine.hidden = !run;
    if (run) {
      this.runLine.textContent = `last Execute: run ${run.id} ${run.status}` + (run.error ? ` — ${run.error}` : '');
      this.runLine.className = `status-${run.status}`;
      this.runLine.href = `#/run/${run.id}`;
    }
  }

  async readState(resetGoal) {
    const answer = await get(`/cells/${encodeURIComponent(this.cell.id)}/state?backend=${this.backend}`);
    if (this.closed) return;
    this.robot = answer.joints;
    this.info.robot = answer.joints;
    this.stage.setJoints(answer.joints);
    if (resetGoal) {
      this.goalJoints = { ...answer.joints };
      this.goal.setJoints(this.goalJoints);
    }
    this.syncSliders();
  }

  async doPlan() {
    this.status.textContent = 'planning…';
    this.planButton.disabled = true;
    const scaling = Number(this.scaling.value);
    try {
      await this.readState(false);
      const plan = await post('/viewer/plan', {
        cell: this.cell.id, group: this.group.name, joints: this.groupValues(this.goalJoints),
        obstacles: this.obstacles,
        backend: this.backend, velocity_scaling: scaling > 0 && scaling <= 1 ? scaling : 0.5,
      });
      this.plan = plan;
      this.info.planned = { duration: plan.duration, samples: plan.times.length, joint_names: plan.joint_names };
      this.goal.showTrajectory(plan, this.goalJoints);
    } finally {
      this.refresh();
    }
  }

  async doExecute() {
    const plan = this.plan;
    if (!plan) return;
    const start = Object.fromEntries(plan.joint_names.map((n, i) => [n, plan.positions[0][i]]));
    const scaling = Number(this.scaling.value);
    const accepted = await post(`/viewer/cells/${encodeURIComponent(this.cell.id)}/execute`, {
      group: this.group.name, joints: this.groupValues(this.goalJoints), backend: this.backend,
      velocity_scaling: scaling > 0 && scaling <= 1 ? scaling : 0.5, start, obstacles: this.obstacles,
    });
    this.run = { id: accepted.run_id, status: 'running', done: false };
    this.info.run = this.run;
    this.plan = null;
    this.refresh();
    await this.follow(this.run);
  }

  // Poll the backend's joints (the solid robot moves) and the run, until it ends.
  async follow(run) {
    while (!this.closed && run.status === 'running') {
      await new Promise((r) => setTimeout(r, POLL_MS));
      const [, detail] = await Promise.all([
        this.readState(false), get(`/runs/${encodeURIComponent(run.id)}`)]);
      run.status = detail.status;
      run.error = detail.error;
    }
    if (this.closed) return;
    await this.readState(false);
    run.done = true;
    this.refresh();
  }

  // Teach: the robot's state (as its backend reports it) stored as a named pose of the
  // group on the server (PUT /cells/{id}/poses/{name}); it becomes a goal here too.
  async doTeach(name) {
    if (!/^[A-Za-z_][A-Za-z0-9_-]{0,63}$/.test(name)) {
      throw new Error(`'name' must be a letter or _ then letters, digits, _ or - (got ${JSON.stringify(name)})`);
    }
    const taught = await request('PUT', `/cells/${encodeURIComponent(this.cell.id)}/poses/${encodeURIComponent(name)}`,
      { group: this.group.name, backend: this.backend });
    const known = name in this.group.poses;
    this.group.poses[name] = taught.joints;
    const select = this.poseSelects.get(this.group.name);
    if (select && !known) select.append(this.ui.el('option', { value: name, textContent: name }));
    this.info.taught = taught;
  }

  // Jog: one joint of the robot moved by a step (within its limits) as an Execute.
  async doJog(name, delta, lo, hi) {
    if (this.run && this.run.status === 'running') return;
    await this.readState(false);
    const joints = this.groupValues(this.robot);
    joints[name] = Math.min(hi, Math.max(lo, joints[name] + delta));
    const scaling = Number(this.scaling.value);
    const accepted = await post(`/viewer/cells/${encodeURIComponent(this.cell.id)}/execute`, {
      group: this.group.name, joints, backend: this.backend,
      velocity_scaling: scaling > 0 && scaling <= 1 ? scaling : 0.5, obstacles: this.obstacles,
    });
    this.run = { id: accepted.run_id, status: 'running', done: false, jog: name };
    this.info.run = this.run;
    this.refresh();
    await this.follow(this.run);
  }

  async doStop() {
    if (this.run && this.run.status === 'running') await post(`/runs/${encodeURIComponent(this.run.id)}/cancel`);
  }
}
