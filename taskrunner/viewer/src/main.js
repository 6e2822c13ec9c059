// The taskrunner web view: Cell, Task, Run and Runs views over one 3D stage.
// Routes live in the URL's hash (#/cell/ID, #/task/NAME, #/run/ID, #/runs); the token
// never does: it is typed into the page and kept in this tab's session storage.

import { ApiError, followEvents, get, getToken, post, setToken } from './api.js';
import { CellView } from './scene3d.js';
import { GoalView } from './goal3d.js';
import { PlanPanel } from './planpanel.js';
import { Timeline, sample } from './timeline.js';
import { drawPlot } from './plot.js';
import { TreeView, shortLocation } from './tree.js';
import { TreeGraph } from './graph.js';
import { Gantt } from './gantt.js';

const $ = (id) => document.getElementById(id);
const el = (tag, props, ...children) => {
  const e = document.createElement(tag);
  Object.assign(e, props || {});
  for (const c of children) e.append(c);
  return e;
};

const state = {
  view: null, cellId: null, cell: null, timeline: null, time: 0, playing: false,
  speed: 1, selected: -1, live: null, lastFrame: 0, follow: true, userScrub: false,
};
const debug = (window.__viewer = { firstFrame: null, successOrder: [], errors: [], state });
const stage = new CellView($('view3d'));
debug.stage = stage;
const goal = new GoalView(stage);
debug.goal = goal;
stage.onFirstFrame = () => { debug.firstFrame = performance.now(); };

function notice(text, isError) {
  const n = $('notice');
  n.hidden = !text;
  n.textContent = text || '';
  n.className = isError ? 'error' : '';
}

function explain(err) {
  if (err instanceof ApiError && err.status === 401) {
    return 'This server needs its token: type it in the box at the top right (it stays in this tab only).';
  }
  const detail = err instanceof ApiError ? err.detail : err.message;
  return typeof detail === 'string' ? detail : JSON.stringify(detail);
}

async function guarded(work) {
  try {
    return await work();
  } catch (err) {
    if (err.name === 'AbortError') return undefined;
    notice(explain(err), true);
    return undefined;
  }
}

// ------------------------------------------------------------------ token
$('token').value = getToken() ? '••••••••' : '';
$('token-form').addEventListener('submit', (ev) => {
  ev.preventDefault();
  const value = $('token').value.trim();
  if (value && !value.startsWith('••')) setToken(value);
  $('token').value = getToken() ? '••••••••' : '';
  notice('');
  route();
});
$('token-forget').addEventListener('click', () => { setToken(''); $('token').value = ''; });

// ------------------------------------------------------------------ 3D cell
async function showCell(cellId) {
  if (state.cellId === cellId && state.cell) return state.cell;
  const cell = await get(`/viewer/cells/${encodeURIComponent(cellId)}`);
  state.cellId = cellId;
  state.cell = cell;
  goal.unload();
  stage.loadCell(cell);
  stage.setFrames($('frames').checked);
  stage.setLabels($('labels').checked);
  if ($('collision').checked) await showCollision(true);
  return cell;
}
$('frames').addEventListener('change', () => stage.setFrames($('frames').checked));
$('labels').addEventListener('change', () => stage.setLabels($('labels').checked));
$('fit').addEventListener('click', () => stage.fitView());

// The planner's collision geometry, fetched once per cell shown.
async function showCollision(on) {
  if (on && !stage.collision && state.cellId) {
    const cellId = state.cellId;
    const data = await get(`/viewer/cells/${encodeURIComponent(cellId)}/collision`);
    if (state.cellId !== cellId) return;
    stage.setCollision(data);
    debug.collision = data;
  }
  stage.setCollisionVisible(on);
}
$('collision').addEventListener('change', () => guarded(() => showCollision($('collision').checked)));

// ------------------------------------------------------------------ tree: list or graph
// The list in the side panel, or the graph under the 3D view (the choice kept in the tab).
function treePanel(box) {
  const list = new TreeView(box);
  const graph = new TreeGraph($('graph-pane'), (node) => selectMotionOf(node));
  debug.graph = graph;
  const buttons = ['list', 'graph'].map((m) => el('button', { type: 'button', textContent: m, id: `tree-${m}` }));
  const setMode = (mode) => {
    sessionStorage.setItem('taskrunner.treeMode', mode);
    buttons.forEach((b) => b.classList.toggle('active', b.textContent === mode));
    box.hidden = mode === 'graph';
    $('graph-pane').hidden = mode !== 'graph';
    $('stage').classList.toggle('split', mode === 'graph');
    stage.resize();
    if (mode === 'graph') graph.home();
  };
  buttons.forEach((b) => b.addEventListener('click', () => setMode(b.textContent)));
  const toggle = el('span', { className: 'tree-mode' }, ...buttons);
  return {
    list, graph, toggle,
    start() { setMode(sessionStorage.getItem('taskrunner.treeMode') || 'list'); },
    show(tree) { list.show(tree); graph.show(tree); },
    showFromEvents(name, events) { list.showFromEvents(name, events); graph.show(list.root); },
    apply(e) { list.apply(e); graph.apply(e); },
    pinProblems(problems) { list.pinProblems(problems); },
  };
}

function closeGraph() {
  $('stage').classList.remove('split');
  $('graph-pane').hidden = true;
  $('graph-pane').textContent = '';
  debug.graph = null;
}

// The timeline at a motion: by its event's seq, or the last of a tree node.
function selectMotion(index) {
  const tl = state.timeline;
  if (!tl || index < 0) return;
  setPlaying(false);
  state.selected = index;
  applyTime(tl.motions[index].start);
}
function selectMotionOf(node) {
  const tl = state.timeline;
  if (!tl) return;
  let found = -1;
  tl.motions.forEach((m, i) => { if (m.node === node.name && (m.location || null) === (node.location || null)) found = i; });
  selectMotion(found);
}

// ------------------------------------------------------------------ timeline
function setTimeline(replay) {
  state.timeline = replay ? new Timeline(replay) : null;
  state.time = 0;
  state.selected = -1;
  $('timeline').hidden = !replay;
  $('timeline').classList.remove('gantt-only');
  if (!replay) { $('gantt').hidden = true; $('gantt').textContent = ''; state.gantt = null; }
  renderMotions();
  applyTime(0);
  stage.resize();
}

function renderMotions() {
  const list = $('motions');
  list.textContent = '';
  if (!state.timeline) return;
  state.timeline.motions.forEach((m, i) => {
    const cut = m.ran < m.trajectory.duration - 1e-3 ? ` (stopped at ${m.ran.toFixed(2)})` : '';
    const li = el('li', { textContent: `${m.node} · ${m.trajectory.duration.toFixed(2)} s${cut}`,
      title: m.location || '' });
    li.addEventListener('click', () => { state.selected = i; state.time = m.start; applyTime(state.time); });
    list.appendChild(li);
  });
}

function applyTime(t) {
  const tl = state.timeline;
  if (!tl) return;
  state.time = Math.max(0, Math.min(t, tl.duration));
  const scene = tl.sceneAt(state.time);
  stage.setJoints(scene.joints);
  stage.setObjects(withCellObjects(scene.objects));
  $('clock').textContent = `${state.time.toFixed(2)} / ${tl.duration.toFixed(2)} s`;
  if (!state.userScrub) $('scrub').value = tl.duration ? Math.round((1000 * state.time) / tl.duration) : 0;
  const items = $('motions').children;
  for (let i = 0; i < items.length; i++) {
    items[i].classList.toggle('playing', i === scene.motion);
    items[i].classList.toggle('selected', i === state.selected);
  }
  const shown = state.selected >= 0 ? state.selected : scene.motion;
  const motion = shown >= 0 ? tl.motions[shown] : null;
  const cursor = motion ? state.time - motion.start : null;
  drawPlot($('plot'), motion, state.cell ? state.cell.joints : [], cursor);
  debug.time = state.time;
  debug.motion = scene.motion;
}

function withCellObjects(objects) {
  return objects && objects.length ? objects : (state.cell ? state.cell.objects : []);
}

function tick(now) {
  if (!state.playing || !state.timeline) return;
  const dt = state.lastFrame ? (now - state.lastFrame) / 1000 : 0;
  state.lastFrame = now;
  const end = state.timeline.duration;
  let t = state.time + dt * state.speed;
  if (t >= end) {
    t = end;
    if (!(state.live && state.follow)) setPlaying(false);
  }
  applyTime(t);
  if (state.playing) requestAnimationFrame(tick);
}

function setPlaying(on) {
  if (on && state.timeline && state.time >= state.timeline.duration && !state.live) state.time = 0;
  state.playing = on;
  state.lastFrame = 0;
  $('play').textContent = on ? '❚❚ pause' : '▶ play';
  if (on) requestAnimationFrame(tick);
}

$('play').addEventListener('click', () => setPlaying(!state.playing));
$('speed').addEventListener('change', () => { state.speed = Number($('speed').value); });
$('follow').addEventListener('change', () => { state.follow = $('follow').checked; });
$('scrub').addEventListener('input', () => {
  if (!state.timeline) return;
  state.userScrub = true;
  setPlaying(false);
  applyTime((Number($('scrub').value) / 1000) * state.timeline.duration);
  state.userScrub = false;
});

// ------------------------------------------------------------------ views
const side = $('side');

async function viewCell(cellId) {
  const cells = await get('/cells');
  const id = cellId || (cells.find((c) => c.id === 'servo_arm_pair') || cells[0] || {}).id;
  if (!id) { side.textContent = 'no cells'; return; }
  const picker = el('select', {}, ...cells.map((c) => el('option', { value: c.id, textContent: c.id, selected: c.id === id })));
  picker.addEventListener('change', () => { location.hash = `#/cell/${picker.value}`; });
  side.append(el('h2', { textContent: 'Cell' }), picker);
  setTimeline(null);
  const cell = await showCell(id);
  side.append(el('p', { textContent: cell.description || '' }));
  stage.setObjects(cell.objects);
  goal.load(cell);
  const panel = new PlanPanel({ el, side, guarded }, stage, goal, cell, debug);
  state.panel = panel;
  await panel.build();
}

async function viewTask(taskName) {
  const tasks = await get('/viewer/tasks');
  const name = taskName || tasks[0];
  const picker = el('select', {}, ...tasks.map((t) => el('option', { value: t, textContent: t, selected: t === name })));
  picker.addEventListener('change', () => { location.hash = `#/task/${picker.value}`; });
  const checkButton = el('button', { type: 'button', textContent: 'check' });
  const previewButton = el('button', { type: 'button', textContent: 'plan only (preview)' });
  const summary = el('div', { className: 'banner', textContent: 'compiling…' });
  const treeBox = el('div');
  const tree = treePanel(treeBox);
  side.append(el('h2', { textContent: 'Task' }), picker, el('div', { className: 'row-ctl' }, checkButton, previewButton), summary,
    el('h2', {}, 'Tree', tree.toggle), treeBox);
  setTimeline(null);
  if (!name) { summary.textContent = 'no tasks'; return; }
  tree.start();
  const compiled = await post('/viewer/tasks/tree', { task: name });
  tree.show(compiled.tree);
  summary.textContent = `cell ${compiled.cell}`;
  const cell = await showCell(compiled.cell);
  // where the task starts, with its own objects (from its file), before any planning
  stage.setJoints(compiled.scene.joints);
  stage.setObjects(compiled.scene.objects);
  debug.taskScene = compiled.scene;
  const here = location.hash;
  const runCheck = async () => {
    summary.textContent = 'checking…';
    const report = await post('/tasks/check', { task: name });
    tree.pinProblems(report.problems);
    summary.textContent = report.ok ? `check: ok (${report.steps} steps, cell ${report.cell})`
      : `check: ${report.problems.length} problem(s)`;
    debug.check = report;
    if (location.hash === here) showCheckSchedules(report.schedules || [], cell);
  };
  const runPreview = async () => {
    summary.textContent = 'planning every motion (nothing moves)…';
    const preview = await post('/viewer/tasks/preview', { task: name });
    tree.show(preview.tree);
    summary.textContent = `preview: ${preview.status}, ${preview.motions.length} motions` + (preview.error ? ` — ${preview.error}` : '');
    setTimeline(preview);
    debug.preview = preview;
  };
  checkButton.addEventListener('click', () => guarded(runCheck));
  previewButton.addEventListener('click', () => guarded(runPreview));
  guarded(runCheck);
}

// Each arm's timeline as the check planned it, before anything runs: one Gantt per
// parallel the check scheduled (times from that parallel's start).
function showCheckSchedules(schedules, cell) {
  const box = $('gantt');
  box.textContent = '';
  debug.checkGantts = [];
  const planned = schedules.filter((s) => (s.timeline || []).length);
  box.hidden = !planned.length;
  const footer = $('timeline');
  if (planned.length && footer.hidden) {  // nothing to play yet: the charts alone
    footer.classList.add('gantt-only');
    footer.hidden = false;  // shown first: each chart takes the box's width
  } else if (!planned.length && footer.classList.contains('gantt-only')) {
    footer.classList.remove('gantt-only');
    footer.hidden = true;
  }
  planned.forEach((schedule, i) => {
    const where = schedule.timeline[0].step ? ` (first step ${shortLocation(schedule.timeline[0].step)})` : '';
    const span = schedule.makespan == null ? '' : `, ${schedule.makespan.toFixed(2)} s in all`;
    box.append(el('div', { className: 'gantt-caption',
      textContent: `planned by the check, parallel ${i + 1}${where}: s from its start${span}; nothing has run` }));
    const chart = el('div', { className: 'gantt-chart' });
    box.append(chart);
    const gantt = new Gantt(chart, cell, null);
    gantt.applySchedule(schedule);
    gantt.render();
    debug.checkGantts.push(gantt);
  });
  stage.resize();
}

async function viewRun(runId) {
  if (!runId) {
    const runs = await get('/runs?limit=1');
    if (runs.length) { location.hash = `#/run/${runs[0].run_id}`; return; }
    side.append(el('p', { textContent: 'No runs yet: start one from Runs.' }));
    return;
  }
  const summary = el('div', { className: 'banner', textContent: 'loading…' });
  const story = el('p', { id: 'story', hidden: true });
  const cancel = el('button', { type: 'button', textContent: 'cancel run', hidden: true });
  const treeBox = el('div', { id: 'run-tree' });
  const log = el('div', { id: 'log' });
  const tree = treePanel(treeBox);
  side.append(el('h2', { textContent: `Run ${runId}` }), summary, story, cancel, el('h2', {}, 'Tree', tree.toggle), treeBox,
    el('h2', { textContent: 'Events' }), log);
  cancel.addEventListener('click', () => guarded(async () => { await post(`/runs/${runId}/cancel`); }));
  const detail = await get(`/runs/${encodeURIComponent(runId)}`);
  debug.tree = tree.list;
  tree.start();
  let compiled = null;
  try { compiled = (await get(`/viewer/runs/${encodeURIComponent(runId)}/tree`)).tree; } catch (e) { compiled = null; }
  const cell = await showCell(detail.cell);
  const gantt = new Gantt($('gantt'), cell, (seq) => {
    if (state.timeline) selectMotion(state.timeline.motions.findIndex((m) => m.seq === seq));
  });
  debug.gantt = gantt;
  const describe = (status, error) => {
    summary.textContent = `${detail.task} on ${detail.cell} (${detail.backend}): ${status}` + (error ? ` — ${error}` : '');
    summary.className = `banner status-${status}`;
    debug.runStatus = status;
  };
  // A resumed run and the run it resumes are one story: linked both ways.
  const showStory = (resumes, resumedBy) => {
    const link = (id) => el('a', { href: `#/run/${id}`, textContent: id });
    story.replaceChildren();
    if (resumes) story.append('resumes ', link(resumes));
    if (resumedBy.length) {
      story.append(resumes ? ' · resumed by ' : 'resumed by ');
      resumedBy.forEach((id, k) => story.append(...(k ? [', ', link(id)] : [link(id)])));
    }
    story.hidden = !resumes && !resumedBy.length;
    debug.story = { resumes: resumes || null, resumedBy };
  };
  const logLine = (e) => {
    const where = e.location ? `  (${shortLocation(e.location)})` : '';
    const text = e.kind === 'node_started' ? `▶ ${e.node}${where}`
      : e.kind === 'node_finished' ? `${e.status === 'SUCCESS' ? '✔' : e.status === 'FAILURE' ? '✘' : '■'} ${e.node}${e.message ? ': ' + e.message : ''}`
        : e.kind === 'motion' ? `  motion ${e.message}` : e.kind === 'planned' ? `  planned: ${e.message}` : e.message;
    log.append(`${e.time.toFixed(2).padStart(7)}s  ${text}\n`);
    log.scrollTop = log.scrollHeight;
  };
  if (detail.status !== 'running') {
    const replay = await get(`/viewer/runs/${encodeURIComponent(runId)}/replay`);
    const events = await allEvents(runId, detail);
    if (compiled) tree.show(compiled); else tree.showFromEvents(detail.task, events);
    events.forEach((e) => { tree.apply(e); logLine(e); });
    debug.successOrder = tree.list.successOrder;
    describe(detail.status, detail.error);
    setTimeline(replay);
    showStory(replay.resumes, replay.resumed_by || []);
    state.gantt = gantt;
    events.forEach((e) => gantt.apply(e));
    gantt.render();
    applyTime(replay.motions.length ? state.timeline.duration : 0);
    return;
  }
  // live: the tree and the timeline grow from the event stream
  if (compiled) tree.show(compiled); else tree.showFromEvents(detail.task, []);
  debug.successOrder = tree.list.successOrder;
  debug.runLive = true;
  describe('running');
  cancel.hidden = false;
  const replay = { motions: [], first_scene: null, final_scene: null };
  setTimeline(replay);
  state.gantt = gantt;
  const controller = new AbortController();
  state.live = controller;
  state.follow = $('follow').checked;
  setPlaying(true);
  const motions = replay.motions;
  await followEvents(runId, (e) => {
    tree.apply(e);
    if (state.gantt === gantt) gantt.apply(e);
    logLine(e);
    if (e.kind === 'run_started') {
      replay.first_scene = e.data.scene || null;
      if (e.data.resumes) showStory(e.data.resumes, []);
    } else if (e.kind === 'motion') motions.push({ seq: e.seq, node: e.node, location: e.location, time: e.time, trajectory: e.data.trajectory, scene: e.data.scene, executed: null });
    else if (e.kind === 'physics') {
      const m = [...motions].reverse().find((x) => x.node === e.node && !x.physics);
      if (m) m.physics = e.data;
    } else if (e.kind === 'node_finished' && e.data.executed) {
      const m = [...motions].reverse().find((x) => x.node === e.node && x.executed == null);
      if (m) m.executed = e.data.executed.until;
    } else if (e.kind === 'run_finished') {
      replay.final_scene = e.data.scene || null;
      describe(e.status, e.status === 'succeeded' ? null : e.message);
      cancel.hidden = true;
    }
    if (e.kind === 'motion' || e.kind === 'physics' || e.kind === 'run_finished' || (e.kind === 'node_finished' && e.data.executed)) {
      const t = state.time;
      state.timeline = new Timeline(replay);
      renderMotions();
      applyTime(t);
      if (e.kind === 'run_finished') {
        state.live = null;
        if (e.status === 'succeeded') setPlaying(true);
        else { setPlaying(false); applyTime(state.timeline.duration); } // where it stopped
      }
    }
  }, controller.signal);
  if (state.live === controller) state.live = null;
}

// A recorded run's events, every page of them (GET /runs/{id} answers up to 1000).
async function allEvents(runId, detail) {
  const events = [...detail.events];
  let more = detail.events_more;
  while (more && events.length) {
    const since = events[events.length - 1].seq;
    const page = await get(`/runs/${encodeURIComponent(runId)}?since=${since}&limit=10000`);
    events.push(...page.events);
    more = page.events_more && page.events.length > 0;
  }
  return events;
}

async function viewRuns() {
  setTimeline(null);
  const tasks = await get('/viewer/tasks');
  const task = el('select', { id: 'start-task' }, ...tasks.map((t) => el('option', { value: t, textContent: t })));
  const backend = el('select', { id: 'start-backend' }, el('option', { textContent: 'sim' }), el('option', { textContent: 'mock' }));
  const speed = el('input', { id: 'start-speed', type: 'number', value: '4', min: '0.1', step: '0.1', style: 'width:5em' });
  const params = el('input', { id: 'start-params', placeholder: '{"place_y": -0.1}', size: 22 });
  const start = el('button', { id: 'start-run', type: 'button', textContent: 'start' });
  start.addEventListener('click', () => guarded(async () => {
    const body = { task: task.value, backend: backend.value };
    if (backend.value === 'sim') body.speed = Number(speed.value);
    if (params.value.trim()) body.parameters = JSON.parse(params.value);
    const run = await post('/runs', body);
    location.hash = `#/run/${run.run_id}`;
  }));
  side.append(el('h2', { textContent: 'Start a run' }),
    el('label', { className: 'row' }, 'task ', task), el('label', { className: 'row' }, 'backend ', backend, ' speed ', speed),
    el('label', { className: 'row' }, 'parameters ', params), start, el('h2', { textContent: 'Runs' }));
  const table = el('table', { className: 'runs' });
  side.append(table);
  const runs = await get('/runs?limit=100');
  table.append(el('tr', {}, ...['run', 'task', 'status', ''].map((h) => el('th', { textContent: h }))));
  for (const run of runs) {
    const link = el('a', { href: `#/run/${run.run_id}`, textContent: run.run_id });
    const action = el('td');
    if (run.status === 'running') {
      const b = el('button', { type: 'button', textContent: 'cancel' });
      b.addEventListener('click', () => guarded(async () => { await post(`/runs/${run.run_id}/cancel`); route(); }));
      action.append(b);
    }
    table.append(el('tr', {}, el('td', {}, link), el('td', { textContent: run.task }),
      el('td', { textContent: run.status, className: `status-${run.status}` }), action));
  }
}

// ------------------------------------------------------------------ routing
async function route() {
  if (state.live) { state.live.abort(); state.live = null; }
  if (state.panel) { state.panel.close(); state.panel = null; }
  closeGraph();
  setPlaying(false);
  const [, view = 'cell', arg = ''] = location.hash.split('/');
  state.view = view;
  document.querySelectorAll('header nav a').forEach((a) => a.classList.toggle('active', a.dataset.view === view));
  side.textContent = '';
  notice('');
  const id = decodeURIComponent(arg);
  if (!(await mayRead())) return;
  const views = { cell: viewCell, task: viewTask, run: viewRun, runs: viewRuns };
  await guarded(() => (views[view] || viewCell)(id));
}

// Without a token, ask for it before any data request (a server that needs it would
// answer 401), unless the user chose to try reads without one (servers with open reads).
async function mayRead() {
  if (getToken() || sessionStorage.getItem('taskrunner.anonymous')) return true;
  const health = await guarded(() => get('/health'));
  if (!health || !health.auth) return Boolean(health);
  notice('This server needs its token: type it in the box at the top right (it stays in this tab only).');
  const open = el('button', { type: 'button', textContent: 'browse without a token (servers with open reads)' });
  open.addEventListener('click', () => { sessionStorage.setItem('taskrunner.anonymous', '1'); route(); });
  side.append(el('p', { textContent: 'No token yet.' }), open);
  return false;
}

window.addEventListener('hashchange', route);
window.addEventListener('error', (e) => debug.errors.push(String(e.message)));
route();
