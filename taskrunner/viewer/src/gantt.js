// Each arm's timeline for a run: a Gantt chart of its motions, waits and holds on the
// run's schedule (task time, s), one row per robot of the cell, built from the run's
// events as they come (live) or from its record:
//
// - a `motion` event starts at `sent` (when it really started; `start` when absent) and
//   lasts for the seconds its leaf's `node_finished` says ran (`executed.until`), else
//   its trajectory's duration; it is drawn on the row of every robot whose joints it moves
//   (a joined `go` of a parallel moves two);
// - a `wait` event with `since` and `until` is drawn over that span; one with `hold`
//   (held until another branch moved on) spans from where the arm's previous motion
//   ended to where its held motion starts. A wait lands on the row of the next motion
//   of its step (same file:line), since a wait says which step waited, not which arm;
//   a `wait` step's (it gives its branch, `lane`) on the rows of its branch's motions
//   (the next one, else the last; a wait of the whole task, on every arm's row), and in
//   a check's schedule on the rows of the `joints` it gives.
//
// Before anything runs, the check's schedule of a parallel (`timeline` and `waits` of a
// `schedules` item of /tasks/check) is drawn the same way: `applySchedule` turns each
// planned motion and each inserted wait into the events a run would give.

const SVG = 'http://www.w3.org/2000/svg';
const ROW = 24;
const AXIS = 20;
const LEFT = 96;

// Whether the branch `inner` (a motion's `lane`: [[parallel, branch], …]) is `outer` or
// inside it.
const within = (inner, outer) => outer.length <= inner.length
  && outer.every((k, i) => k[0] === inner[i][0] && k[1] === inner[i][1]);

const svg = (tag, attrs, text) => {
  const e = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
  if (text !== undefined) e.textContent = text;
  return e;
};

// A tick step of about a tenth of the span (1, 2 or 5 times a power of ten), s.
function tickStep(span) {
  const raw = Math.max(span, 1e-3) / 8;
  const p = 10 ** Math.floor(Math.log10(raw));
  return [1, 2, 5, 10].map((m) => m * p).find((s) => s >= raw);
}

export class Gantt {
  // cell: GET /viewer/cells/{id} (robots and each joint's robot); onSelect(seq): a
  // motion's bar was clicked.
  constructor(container, cell, onSelect) {
    this.container = container;
    this.onSelect = onSelect || null;
    this.robotOf = new Map(cell.joints.map((j) => [j.name, j.robot]));
    this.arms = cell.robots.map((r) => r.name);
    this.motions = [];        // {seq, node, location, arms, start, duration, ran, done}
    this.waits = [];          // {kind: 'wait'|'hold', node, location, since, until, arm, message, seq}
    this.pending = [];        // waits whose arm is not known yet
    this._drawn = false;
    this._queued = false;
  }

  // One run event.
  apply(e) {
    const d = e.data || {};
    if (e.kind === 'motion' && d.trajectory) {
      const traj = d.trajectory;
      const arms = [...new Set(traj.joints.map((j) => this.robotOf.get(j)).filter(Boolean))];
      const duration = traj.times.length ? traj.times[traj.times.length - 1] : 0;
      const start = Number(d.sent !== undefined ? d.sent : (d.start || 0));
      const lane = d.lane || [];
      const motion = { seq: e.seq, node: e.node, location: e.location, arms, start, duration, ran: duration, done: false, lane };
      this.motions.push(motion);
      for (const wait of this.pending.filter((w) => (w.lane ? within(lane, w.lane) : w.location === e.location))) {
        wait.arms = arms;
        if (wait.kind === 'hold') {
          wait.until = start;
          wait.since = Math.min(start, this._armEnd(arms, motion));
        }
      }
      this.pending = this.pending.filter((w) => !w.arms);
    } else if (e.kind === 'node_finished' && d.executed && d.executed.until !== undefined) {
      const m = [...this.motions].reverse().find((x) => x.node === e.node && x.location === e.location && !x.done);
      if (m) { m.ran = Math.min(Number(d.executed.until), m.duration); m.done = true; }
    } else if (e.kind === 'wait') {
      const timed = d.since !== undefined && d.until !== undefined;
      const wait = { kind: timed ? 'wait' : 'hold', node: e.node, location: e.location, seq: e.seq,
        since: timed ? Number(d.since) : null, until: timed ? Number(d.until) : null,
        message: e.message, arms: null, lane: timed && Array.isArray(d.lane) ? d.lane : null };
      if (!timed && !d.hold) return;
      if (Array.isArray(d.joints) && d.joints.length) {  // a check's wait step: its branch's joints
        wait.arms = [...new Set(d.joints.map((j) => this.robotOf.get(j)).filter(Boolean))];
        this.waits.push(wait);
        this.draw();
        return;
      }
      if (wait.lane && !wait.lane.length) {  // a wait of the whole task: every arm waits
        wait.arms = [...this.arms];
        this.waits.push(wait);
        this.draw();
        return;
      }
      if (timed) {  // the span of a hold of this step, now known: it replaces the hold
        const held = (w) => w.kind === 'hold' && !w.arms && w.node === e.node && w.location === e.location;
        this.waits = this.waits.filter((w) => !held(w));
        this.pending = this.pending.filter((w) => !held(w));
      }
      this.waits.push(wait);
      this.pending.push(wait);
    } else if (e.kind === 'run_finished') {
      // A branch's wait step after its last motion: on the rows of that branch's motions.
      for (const wait of this.pending.filter((w) => w.lane)) {
        const last = [...this.motions].reverse().find((m) => within(m.lane, wait.lane));
        if (last) wait.arms = last.arms;
      }
      this.pending = this.pending.filter((w) => !w.arms);
    } else {
      return;
    }
    this.draw();
  }

  // A check's schedule of one parallel (/tasks/check `schedules[i]`): its planned motions
  // and waits, on the parallel's own clock (s from its start).
  applySchedule(schedule) {
    const items = [];
    (schedule.timeline || []).forEach((m, i) => {
      if (m.start == null || m.end == null) return;
      const where = m.step || '';
      items.push([m.start, 1, { seq: i + 1, kind: 'motion', node: `planned ${where.split('/').pop()}`, location: m.step,
        data: { start: m.start, sent: m.start, trajectory: { joints: m.joints, times: [0, m.end - m.start] } } }]);
    });
    for (const w of schedule.waits || []) {  // before the motion its step starts after it
      if (w.since == null || w.until == null) continue;
      items.push([w.until, 0, { seq: 0, kind: 'wait', node: 'wait', location: w.step, message: w.reason,
        data: { since: w.since, until: w.until, ...(w.joints ? { joints: w.joints } : {}) } }]);
    }
    items.sort((a, b) => a[0] - b[0] || a[1] - b[1]);
    for (const [, , e] of items) this.apply(e);
  }

  // Where the arms' last motion before `motion` ended (s on the schedule; 0 if none).
  _armEnd(arms, motion) {
    let end = 0;
    for (const m of this.motions) {
      if (m === motion || !m.arms.some((a) => arms.includes(a))) continue;
      if (m.start <= motion.start) end = Math.max(end, m.start + m.ran);
    }
    return end;
  }

  // Each arm's bars: {arm: [{kind, node, location, start, end, seq}]} (waits not yet
  // tied to an arm are left out).
  rows() {
    const rows = Object.fromEntries(this.arms.map((a) => [a, []]));
    for (const m of this.motions) {
      for (const arm of m.arms) {
        (rows[arm] = rows[arm] || []).push({ kind: 'motion', node: m.node, location: m.location,
          start: m.start, end: m.start + m.ran, seq: m.seq });
      }
    }
    for (const w of this.waits) {
      if (!w.arms || w.since == null || w.until == null || w.until <= w.since) continue;
      for (const arm of w.arms) {
        (rows[arm] = rows[arm] || []).push({ kind: w.kind, node: w.node, location: w.location,
          start: w.since, end: w.until, seq: w.seq, message: w.message });
      }
    }
    for (const bars of Object.values(rows)) bars.sort((a, b) => a.start - b.start);
    return rows;
  }

  // Redraw on the next frame (events come in bursts).
  draw() {
    if (this._queued) return;
    this._queued = true;
    requestAnimationFrame(() => { this._queued = false; this.render(); });
  }

  render() {
    const rows = this.rows();
    const arms = Object.keys(rows).filter((a) => rows[a].length || this.arms.includes(a));
    const end = Math.max(1e-3, ...Object.values(rows).flat().map((b) => b.end));
    const width = Math.max(200, this.container.clientWidth || 600);
    const height = AXIS + arms.length * ROW + 4;
    const scale = (width - LEFT - 10) / end;
    const x = (t) => LEFT + t * scale;
    const root = svg('svg', { class: 'gantt', width, height, viewBox: `0 0 ${width} ${height}` });
    const step = tickStep(end);
    for (let t = 0; t <= end + 1e-9; t += step) {
      root.appendChild(svg('line', { x1: x(t), x2: x(t), y1: AXIS - 4, y2: height, class: 'tick' }));
      root.appendChild(svg('text', { x: x(t) + 2, y: AXIS - 7, class: 'tick-label' }, `${+t.toFixed(3)} s`));
    }
    arms.forEach((arm, i) => {
      const y = AXIS + i * ROW;
      root.appendChild(svg('text', { x: 4, y: y + ROW / 2 + 4, class: 'arm' }, arm));
      root.appendChild(svg('line', { x1: LEFT, x2: width, y1: y + ROW, y2: y + ROW, class: 'lane' }));
      for (const bar of rows[arm]) {
        const inset = bar.kind === 'motion' ? 3 : 7;
        const rect = svg('rect', { x: x(bar.start), y: y + inset, width: Math.max(1.5, (bar.end - bar.start) * scale),
          height: ROW - 2 * inset, class: `bar ${bar.kind}`, 'data-seq': bar.seq, 'data-arm': arm,
          'data-start': bar.start, 'data-end': bar.end });
        const what = bar.kind === 'motion' ? bar.node : `${bar.kind}: ${bar.message || bar.node}`;
        rect.appendChild(svg('title', {}, `${what}\n${bar.location || ''}\n${bar.start.toFixed(2)}–${bar.end.toFixed(2)} s`));
        if (bar.kind === 'motion' && this.onSelect) rect.addEventListener('click', () => this.onSelect(bar.seq));
        root.appendChild(rect);
      }
    });
    this.container.textContent = '';
    this.container.appendChild(root);
    this.container.hidden = !this.motions.length && !this.waits.length;
    this._drawn = true;
  }
}
