// A behaviour tree drawn as a graph, top-down as Groot2 draws it: composites and leaves
// as boxes, each parent above its children, edges between them. Status colours follow
// the run's events (as the list does, keyed by name and file:line); hovering a node
// shows its file:line, a click on a leaf shows what the run said about it (its feedback,
// the motion planned and sent, its waits). Pan by dragging, zoom with the wheel.
//
// Layout (a tidy tree for top-down drawing): leaves take consecutive columns in the
// tree's order, a parent is centred over its first and last child, depth gives the row.
// Each subtree then owns a contiguous band of columns, so no two boxes or edges cross.

import { keyOf, rollUp, shortLocation } from './tree.js';

const SVG = 'http://www.w3.org/2000/svg';
const W = 150;       // node box, px
const H = 38;
const GAP_X = 14;
const GAP_Y = 34;
const PAD = 16;
const MARKS = { SUCCESS: '✔', FAILURE: '✘', RUNNING: '▶', INVALID: '■' };

const svg = (tag, attrs, text) => {
  const e = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
  if (text !== undefined) e.textContent = text;
  return e;
};

// Column and row of every node: {node, parent, depth, x (column centre), children}.
export function layoutTree(tree) {
  const placed = [];
  let column = 0;
  let depth = 0;
  const place = (node, parent, level) => {
    const entry = { node, parent, depth: level, x: 0, children: [] };
    placed.push(entry);
    depth = Math.max(depth, level);
    if (!node.children || !node.children.length) {
      entry.x = column++;
    } else {
      for (const child of node.children) entry.children.push(place(child, entry, level + 1));
      entry.x = (entry.children[0].x + entry.children[entry.children.length - 1].x) / 2;
    }
    return entry;
  };
  if (tree) place(tree, null, 0);
  return { nodes: placed, columns: column, rows: depth + 1 };
}

// A child's name without its parent's ("pick bar: approach" under "pick bar").
function label(entry) {
  const name = entry.node.name;
  const parent = entry.parent && entry.parent.node.name;
  return parent && name.startsWith(parent + ': ') ? name.slice(parent.length + 2) : name;
}

function clip(text, chars) {
  return text.length > chars ? text.slice(0, chars - 1) + '…' : text;
}

export class TreeGraph {
  // container: the element the graph fills; onSelect(leaf, facts): a leaf was clicked.
  constructor(container, onSelect) {
    this.container = container;
    this.onSelect = onSelect || null;
    this.entries = [];
    this.byKey = new Map();   // leaf key -> entry
    this.facts = new Map();   // leaf key -> what the run said about it
    this.selected = null;
    this.follow = true;
    this.view = { x: 0, y: 0, k: 1 };
    this.svg = svg('svg', { class: 'tree-graph' });
    this.layer = svg('g');
    this.svg.appendChild(this.layer);
    this.detail = document.createElement('div');
    this.detail.className = 'graph-detail';
    this.detail.hidden = true;
    this.tip = document.createElement('div');
    this.tip.className = 'graph-tip';
    this.tip.hidden = true;
    const tools = document.createElement('div');
    tools.className = 'graph-tools';
    for (const [text, act] of [['fit', () => this.fit()], ['top', () => this.home()]]) {
      const b = document.createElement('button');
      b.type = 'button';
      b.textContent = text;
      b.addEventListener('click', act);
      tools.appendChild(b);
    }
    container.textContent = '';
    container.append(this.svg, tools, this.detail, this.tip);
    this._panZoom();
  }

  // A compiled tree ({name, kind, location, status, children}); statuses start from it.
  show(tree) {
    this.layer.textContent = '';
    this.byKey.clear();
    this.facts.clear();
    this.selected = null;
    this.detail.hidden = true;
    const { nodes, columns, rows } = layoutTree(tree);
    this.entries = nodes;
    this.size = { width: columns * (W + GAP_X) - GAP_X + 2 * PAD, height: rows * (H + GAP_Y) - GAP_Y + 2 * PAD };
    const edges = svg('g', { class: 'edges' });
    const boxes = svg('g', { class: 'nodes' });
    this.layer.append(edges, boxes);
    for (const entry of nodes) {
      entry.px = PAD + entry.x * (W + GAP_X);
      entry.py = PAD + entry.depth * (H + GAP_Y);
      if (entry.parent) {
        const x0 = entry.parent.px + W / 2, y0 = entry.parent.py + H;
        const x1 = entry.px + W / 2, y1 = entry.py;
        const ym = (y0 + y1) / 2;
        edges.appendChild(svg('path', { d: `M${x0},${y0} C${x0},${ym} ${x1},${ym} ${x1},${y1}` }));
      }
      const leaf = !entry.node.children || !entry.node.children.length;
      const g = svg('g', { class: 'gnode ' + (leaf ? 'leaf' : 'composite'), transform: `translate(${entry.px},${entry.py})` });
      g.appendChild(svg('rect', { width: W, height: H, rx: leaf ? 4 : 10 }));
      entry.mark = svg('text', { x: 7, y: 15, class: 'mark' }, '·');
      g.appendChild(entry.mark);
      g.appendChild(svg('text', { x: 20, y: 15, class: 'name' }, clip(label(entry), 20)));
      const kind = leaf ? (entry.node.kind || '') : entry.node.kind;
      g.appendChild(svg('text', { x: 7, y: 31, class: 'sub' }, clip(`${kind} · ${shortLocation(entry.node.location)}`, 26)));
      g.addEventListener('mouseenter', () => this._hover(entry));
      g.addEventListener('mouseleave', () => { this.tip.hidden = true; });
      if (leaf) {
        entry.key = keyOf(entry.node.name, entry.node.location);
        g.dataset.key = entry.key;
        this.byKey.set(entry.key, entry);
        this.facts.set(entry.key, { events: [] });
        g.addEventListener('click', (ev) => { ev.stopPropagation(); this.select(entry.key); });
      }
      entry.el = g;
      entry.status = null;
      boxes.appendChild(g);
      if (entry.node.status && entry.node.status !== 'INVALID') this._set(entry, entry.node.status);
    }
    this.home();
  }

  // The root at the top, centred, readable (the whole tree when it fits).
  home() {
    const w = this.container.clientWidth || 800;
    const h = this.container.clientHeight || 400;
    if (!this.size) return;
    // readable: never below 0.75 (a large tree is panned, or fitted with fit())
    const k = Math.min(1, Math.max(0.75, Math.min(w / this.size.width, h / this.size.height)));
    const root = this.entries[0];
    const cx = root ? root.px + W / 2 : this.size.width / 2;
    this.view = { k, x: w / 2 - cx * k, y: 8 };
    if (this.size.width * k <= w) this.view.x = (w - this.size.width * k) / 2;
    this._apply();
  }

  // Scale to the whole tree.
  fit() {
    const w = this.container.clientWidth || 800;
    const h = this.container.clientHeight || 400;
    if (!this.size) return;
    const k = Math.min(w / this.size.width, h / this.size.height, 1.5);
    this.view = { k, x: (w - this.size.width * k) / 2, y: (h - this.size.height * k) / 2 };
    this._apply();
  }

  // Bring an entry into view (kept at the current zoom).
  reveal(entry) {
    const w = this.container.clientWidth || 800;
    const h = this.container.clientHeight || 400;
    const { k } = this.view;
    const sx = this.view.x + entry.px * k, sy = this.view.y + entry.py * k;
    if (sx < 0 || sx + W * k > w) this.view.x = w / 2 - (entry.px + W / 2) * k;
    if (sy < 0 || sy + H * k > h) this.view.y = h / 2 - (entry.py + H / 2) * k;
    this._apply();
  }

  _apply() {
    const { x, y, k } = this.view;
    this.layer.setAttribute('transform', `translate(${x},${y}) scale(${k})`);
  }

  _panZoom() {
    let drag = null;
    this.svg.addEventListener('pointerdown', (ev) => {
      drag = { x: ev.clientX, y: ev.clientY, vx: this.view.x, vy: this.view.y, moved: false };
    });
    this.svg.addEventListener('pointermove', (ev) => {
      if (!drag) return;
      const dx = ev.clientX - drag.x, dy = ev.clientY - drag.y;
      if (!drag.moved && Math.abs(dx) + Math.abs(dy) < 4) return;
      if (!drag.moved) this.svg.setPointerCapture(ev.pointerId);
      drag.moved = true;
      this.follow = false;  // the user looks elsewhere: stop following the run
      this.view.x = drag.vx + dx;
      this.view.y = drag.vy + dy;
      this._apply();
    });
    const end = () => { drag = null; };
    this.svg.addEventListener('pointerup', end);
    this.svg.addEventListener('pointercancel', end);
    this.svg.addEventListener('wheel', (ev) => {
      ev.preventDefault();
      const box = this.svg.getBoundingClientRect();
      const mx = ev.clientX - box.left, my = ev.clientY - box.top;
      const k = Math.min(3, Math.max(0.1, this.view.k * Math.exp(-ev.deltaY / 500)));
      this.view.x = mx - ((mx - this.view.x) * k) / this.view.k;
      this.view.y = my - ((my - this.view.y) * k) / this.view.k;
      this.view.k = k;
      this._apply();
    }, { passive: false });
    this.svg.addEventListener('click', () => { if (this.selected) this.select(null); });
  }

  _hover(entry) {
    const where = entry.node.location || '(no file:line)';
    const status = entry.status ? `  ${entry.status}` : '';
    this.tip.textContent = `${entry.node.name}\n${entry.node.kind}  ${where}${status}`;
    this.tip.hidden = false;
    const { k } = this.view;
    this.tip.style.left = `${Math.max(0, this.view.x + entry.px * k)}px`;
    this.tip.style.top = `${this.view.y + (entry.py + H) * k + 4}px`;
  }

  _set(entry, status) {
    entry.status = status;
    entry.el.setAttribute('class', entry.el.getAttribute('class').replace(/ st-\w+/g, '') + (status ? ' st-' + status : ''));
    entry.mark.textContent = MARKS[status] || '·';
  }

  // Apply one run event: statuses (leaves, rolled up to composites) and a leaf's facts.
  apply(e) {
    if (!e.node) return;
    const key = keyOf(e.node, e.location);
    const entry = this.byKey.get(key);
    if (!entry) return;
    const facts = this.facts.get(key);
    facts.events.push(e);
    if (e.kind === 'node_started' || e.kind === 'node_finished') {
      const status = e.kind === 'node_started' ? 'RUNNING' : e.status;
      this._set(entry, status);
      for (let p = entry.parent; p; p = p.parent) this._set(p, rollUp(p));
      if (status === 'RUNNING' && this.follow) this.reveal(entry);
    }
    if (this.selected === key) this._detail(entry);
  }

  // Statuses by leaf key (for tests and the page's readout).
  statuses() {
    const out = {};
    for (const entry of this.entries) out[entry.key || `${entry.node.name}@${entry.node.location || ''}#${entry.depth}`] = entry.status;
    return out;
  }

  select(key) {
    if (this.selected) {
      const old = this.byKey.get(this.selected);
      if (old) old.el.classList.remove('selected');
    }
    this.selected = key;
    const entry = key ? this.byKey.get(key) : null;
    if (!entry) { this.detail.hidden = true; return; }
    entry.el.classList.add('selected');
    this._detail(entry);
    if (this.onSelect) this.onSelect(entry.node, this.facts.get(key));
  }

  _detail(entry) {
    const facts = this.facts.get(entry.key) || { events: [] };
    const box = this.detail;
    box.textContent = '';
    box.hidden = false;
    const line = (name, value) => {
      const row = document.createElement('div');
      const b = document.createElement('b');
      b.textContent = name + ' ';
      row.append(b, value);
      box.appendChild(row);
    };
    const head = document.createElement('h3');
    head.textContent = entry.node.name;
    box.appendChild(head);
    line('kind', entry.node.kind || 'leaf');
    line('file:line', entry.node.location || '—');
    line('status', entry.status || 'not run');
    for (const e of facts.events) {
      const t = `${e.time.toFixed(2)} s  `;
      if (e.kind === 'node_finished') {
        line('feedback', t + (e.message || e.status));
        const data = Object.entries(e.data || {}).map(([k, v]) => `${k}: ${typeof v === 'object' ? JSON.stringify(v) : v}`);
        if (data.length) line('data', data.join(', '));
      } else if (e.kind === 'planned') {
        const d = e.data || {};
        line('planned', `${e.message}` + (d.planning_time !== undefined ? ` (planned in ${(1000 * d.planning_time).toFixed(0)} ms)` : ''));
      } else if (e.kind === 'motion') {
        const d = e.data || {};
        const traj = d.trajectory || {};
        const at = d.sent !== undefined ? d.sent : d.start;
        line('motion', `${e.message} at ${Number(at || 0).toFixed(2)} s on the schedule; ` +
          `${(traj.joints || []).length} joints, ${(traj.times || []).length} samples` +
          (d.lane && d.lane.length ? `; branch ${JSON.stringify(d.lane)}` : ''));
      } else if (e.kind === 'wait') {
        const d = e.data || {};
        const span = d.since !== undefined ? ` (${d.since.toFixed(2)}–${d.until.toFixed(2)} s)` : d.hold ? ' (held)' : '';
        line('wait', e.message + span);
      } else if (e.kind === 'message') {
        line('message', t + e.message);
      }
    }
  }
}
