// Joint positions and velocities against time for one motion, on a canvas, with the
// joints' limits drawn dashed and a cursor at the playing time.

const COLOURS = ['#d62728', '#1f77b4', '#2ca02c', '#9467bd', '#ff7f0e', '#8c564b', '#e377c2',
  '#17becf', '#7f7f7f', '#bcbd22', '#393b79', '#637939'];

export function drawPlot(canvas, motion, joints, cursor) {
  const dpr = window.devicePixelRatio || 1;
  const w = canvas.clientWidth || 400, h = canvas.clientHeight || 260;
  canvas.width = w * dpr; canvas.height = h * dpr;
  const g = canvas.getContext('2d');
  g.setTransform(dpr, 0, 0, dpr, 0, 0);
  g.clearRect(0, 0, w, h);
  g.font = '11px system-ui, sans-serif';
  if (!motion) {
    g.fillStyle = '#667'; g.fillText('pick a motion to plot its joints', 10, 20);
    return;
  }
  const traj = motion.trajectory;
  const limits = Object.fromEntries((joints || []).map((j) => [j.name, j]));
  const half = (h - 30) / 2;
  panel(g, traj, 'positions', 'position (rad)', 40, 8, w - 150, half - 10, limits, cursor,
    (j) => [limits[j]?.lower, limits[j]?.upper]);
  panel(g, traj, 'velocities', 'velocity (rad/s)', 40, half + 18, w - 150, half - 10, limits,
    cursor, (j) => (limits[j]?.velocity != null ? [-limits[j].velocity, limits[j].velocity] : []));
  traj.joints.forEach((name, i) => {
    g.fillStyle = COLOURS[i % COLOURS.length];
    g.fillText(name, w - 104, 16 + 14 * i);
  });
  g.fillStyle = '#445';
  g.fillText('time (s)', w / 2 - 40, h - 2);
}

function panel(g, traj, key, title, x, y, w, h, limits, cursor, limitOf) {
  const rows = traj[key];
  let lo = Infinity, hi = -Infinity;
  for (const row of rows) for (const v of row) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
  const bounds = traj.joints.map(limitOf);
  for (const b of bounds) for (const v of b) if (v != null && isFinite(v)) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
  if (!(hi > lo)) { hi = lo + 1; lo -= 1; }
  const pad = 0.05 * (hi - lo); lo -= pad; hi += pad;
  const T = traj.duration || traj.times[traj.times.length - 1] || 1;
  const px = (t) => x + (t / T) * w;
  const py = (v) => y + h - ((v - lo) / (hi - lo)) * h;
  g.strokeStyle = '#99a'; g.lineWidth = 1; g.setLineDash([]);
  g.strokeRect(x, y, w, h);
  g.fillStyle = '#445';
  g.fillText(title, x + 4, y + 12);
  g.fillText(hi.toFixed(2), 2, y + 10);
  g.fillText(lo.toFixed(2), 2, y + h);
  g.fillText('0', x - 3, y + h + 11);
  g.fillText(T.toFixed(2), x + w - 20, y + h + 11);
  traj.joints.forEach((name, j) => {
    const colour = COLOURS[j % COLOURS.length];
    g.strokeStyle = colour; g.lineWidth = 1.5; g.setLineDash([]);
    g.beginPath();
    rows.forEach((row, i) => {
      const X = px(traj.times[i]), Y = py(row[j]);
      if (i === 0) g.moveTo(X, Y); else g.lineTo(X, Y);
    });
    g.stroke();
    g.setLineDash([5, 4]); g.lineWidth = 1;
    for (const v of bounds[j]) {
      if (v == null || !isFinite(v)) continue;
      g.beginPath(); g.moveTo(x, py(v)); g.lineTo(x + w, py(v)); g.stroke();
    }
  });
  g.setLineDash([]);
  if (cursor != null && cursor >= 0) {
    g.strokeStyle = '#000'; g.lineWidth = 1;
    g.beginPath(); g.moveTo(px(cursor), y); g.lineTo(px(cursor), y + h); g.stroke();
  }
}
