// A behaviour tree as nested lists: each node with its status and task file:line.
// Leaves take their status from run events (node_started / node_finished), keyed by
// name and file:line (a task may use one name twice); composites show their children's.

const MARKS = { SUCCESS: '✔', FAILURE: '✘', RUNNING: '▶', INVALID: '■', STOPPED: '■' };

export const keyOf = (name, location) => `${name}@${location || ''}`;

export function shortLocation(location) {
  if (!location) return '';
  const cut = location.lastIndexOf('/');
  return cut >= 0 ? location.slice(cut + 1) : location;
}

export class TreeView {
  constructor(container) {
    this.container = container;
    this.nodes = new Map(); // key -> {el, node, parent}
    this.root = null;
    this.successOrder = [];
    this.problems = new Map();
  }

  // A compiled tree ({name, kind, location, children}).
  show(tree) {
    this.container.textContent = '';
    this.nodes.clear();
    this.successOrder = [];
    this.root = tree;
    if (!tree) return;
    const ul = document.createElement('ul');
    ul.className = 'tree';
    ul.appendChild(this._build(tree, null));
    this.container.appendChild(ul);
  }

  // A tree made from events alone (a run whose compiled tree is gone): the leaves in the
  // order they started, under their task step (file:line).
  showFromEvents(name, events) {
    const steps = [];
    const byLocation = new Map();
    const seen = new Set();
    for (const e of events) {
      if (e.kind !== 'node_started' || !e.node) continue;
      const key = keyOf(e.node, e.location);
      if (seen.has(key)) continue;
      seen.add(key);
      let step = byLocation.get(e.location || '');
      if (!step) {
        step = { name: shortLocation(e.location) || 'step', kind: 'sequence', location: e.location, children: [] };
        byLocation.set(e.location || '', step);
        steps.push(step);
      }
      step.children.push({ name: e.node, kind: 'leaf', location: e.location, children: [] });
    }
    const flat = steps.map((s) => (s.children.length === 1 ? s.children[0] : s));
    this.show({ name, kind: 'sequence', location: null, children: flat });
  }

  _build(node, parent) {
    const li = document.createElement('li');
    li.className = 'node';
    const row = document.createElement('div');
    row.className = 'row';
    const mark = document.createElement('span');
    mark.className = 'mark';
    const label = document.createElement('span');
    label.className = 'name';
    label.textContent = node.name;
    const kind = document.createElement('span');
    kind.className = 'kind';
    kind.textContent = node.children.length ? node.kind : '';
    const where = document.createElement('span');
    where.className = 'where';
    where.textContent = shortLocation(node.location);
    where.title = node.location || '';
    row.append(mark, label, kind, where);
    li.appendChild(row);
    const entry = { el: li, mark, node, parent, status: null, children: [] };
    if (!node.children.length) {
      li.dataset.key = keyOf(node.name, node.location);
      this.nodes.set(li.dataset.key, entry);
    }
    if (node.children.length) {
      const ul = document.createElement('ul');
      for (const child of node.children) {
        const childLi = this._build(child, entry);
        ul.appendChild(childLi);
        entry.children.push(childLi._entry);
      }
      li.appendChild(ul);
    }
    li._entry = entry;
    if (node.status && node.status !== 'INVALID') this._set(entry, node.status);
    return li;
  }

  _set(entry, status) {
    entry.status = status;
    entry.el.classList.remove('st-SUCCESS', 'st-FAILURE', 'st-RUNNING', 'st-INVALID');
    if (status) entry.el.classList.add('st-' + status);
    entry.mark.textContent = MARKS[status] || '·';
  }

  // Apply one run event.
  apply(event) {
    if (event.kind !== 'node_started' && event.kind !== 'node_finished') return;
    const entry = this.nodes.get(keyOf(event.node, event.location));
    if (!entry) return;
    const status = event.kind === 'node_started' ? 'RUNNING' : event.status;
    this._set(entry, status);
    if (status === 'SUCCESS') this.successOrder.push(entry.el.dataset.key);
    if (status === 'INVALID') entry.el.title = 'stopped here';
    if (status === 'FAILURE' && event.message) entry.el.title = event.message;
    for (let p = entry.parent; p; p = p.parent) this._set(p, rollUp(p));
  }

  // Pin check problems ({file, line, message}) to the nodes at their file:line (the
  // root when none is).
  pinProblems(problems) {
    this.container.querySelectorAll('.problem').forEach((el) => el.remove());
    for (const problem of problems || []) {
      const where = `${problem.file}:${problem.line}`;
      let target = null;
      for (const li of this.container.querySelectorAll('li.node')) {
        if (li._entry.node.location === where) { target = li; break; }
      }
      target = target || this.container.querySelector('li.node');
      if (!target) continue;
      const note = document.createElement('div');
      note.className = 'problem';
      note.textContent = `✘ line ${problem.line}: ${problem.message}`;
      target.insertBefore(note, target.children[1] || null);
      target.classList.add('has-problem');
    }
  }
}

// A composite's status from its children's ({node, children: [{status}]}).
export function rollUp(entry) {
  const states = entry.children.map((c) => c.status);
  if (states.includes('RUNNING')) return 'RUNNING';
  if (states.includes('FAILURE') && entry.node.kind !== 'fallback') return 'FAILURE';
  if (states.includes('INVALID')) return 'INVALID';
  if (states.length && states.every((s) => s === 'SUCCESS')) return 'SUCCESS';
  if (entry.node.kind === 'fallback' && states.includes('SUCCESS')) return 'SUCCESS';
  return states.some((s) => s) ? 'RUNNING' : null;
}
