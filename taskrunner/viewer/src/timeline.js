// A run's motions laid end to end on one timeline (task time: each motion for as long as
// it ran), and the scene at any time on it: the joints of the motion playing
// (interpolated between its samples) over the scene it started in, objects as they
// were then (attached ones ride on their link). Before the first motion: the run's first
// scene; after the last: its final scene. A motion measured by a physics backend
// (``physics``: joints and object world poses over physics time) shows what was measured:
// its joints, and its free objects where the physics had them.

export class Timeline {
  constructor(replay) {
    this.first = replay.first_scene || null;
    this.final = replay.final_scene || null;
    this.motions = [];
    this.duration = 0;
    for (const m of replay.motions || []) this.add(m);
  }

  add(motion) {
    const traj = motion.trajectory;
    const ran = motion.executed == null ? traj.duration : Math.min(motion.executed, traj.duration);
    this.motions.push(Object.assign({}, motion, { start: this.duration, ran }));
    this.duration += Math.max(ran, 0);
  }

  // Which motion plays at time t (index, or -1 before the first / after the last).
  indexAt(t) {
    for (let i = 0; i < this.motions.length; i++) {
      const m = this.motions[i];
      if (t < m.start + m.ran || (i === this.motions.length - 1 && t <= m.start + m.ran)) {
        return t >= m.start ? i : -1;
      }
    }
    return -1;
  }

  // {joints, objects, motion} at time t.
  sceneAt(t) {
    if (!this.motions.length || t <= 0) {
      const scene = this.first || (this.motions[0] && this.motions[0].scene) || this.final;
      return { joints: scene ? scene.joints : {}, objects: scene ? scene.objects : [], motion: -1 };
    }
    const i = this.indexAt(t);
    if (i < 0 || (t >= this.duration && this.final)) {
      const scene = this.final || this.motions[this.motions.length - 1].scene;
      const joints = Object.assign({}, scene.joints);
      if (!this.final) Object.assign(joints, endOf(this.motions[this.motions.length - 1]));
      return { joints, objects: scene.objects, motion: -1 };
    }
    const m = this.motions[i];
    if (m.physics && m.physics.t && m.physics.t.length) {
      return Object.assign(measuredAt(m, t - m.start), { motion: i });
    }
    const joints = Object.assign({}, m.scene.joints, sample(m.trajectory, t - m.start).positions);
    return { joints, objects: m.scene.objects, motion: i };
  }
}

// Joints and objects of a measured motion at local time tau (s from its start): the
// physics samples from the first one on, linear between samples.
function measuredAt(m, tau) {
  const p = m.physics;
  const times = p.t;
  const n = times.length;
  const at = times[0] + Math.max(0, tau);
  let k = 0;
  while (k < n - 2 && times[k + 1] <= at) k++;
  const k1 = Math.min(k + 1, n - 1);
  const a = times[k1] > times[k] ? Math.min(1, Math.max(0, (at - times[k]) / (times[k1] - times[k]))) : 0;
  const joints = Object.assign({}, m.scene.joints);
  p.joints.forEach((name, j) => { joints[name] = p.q[k][j] + a * (p.q[k1][j] - p.q[k][j]); });
  const objects = (m.scene.objects || []).map((obj) => {
    const track = p.objects && p.objects[obj.name];
    const pose = track && (track[a < 0.5 ? k : k1] || track[k]);
    if (!pose) return obj;
    return Object.assign({}, obj, { pose: { xyz: pose.slice(0, 3), quat: pose.slice(3, 7) },
                                    attached_to: null, held: obj.attached_to || null });
  });
  return { joints, objects };
}

function endOf(motion) {
  return sample(motion.trajectory, motion.ran).positions;
}

// Positions and velocities of a trajectory at time t (s), linear between samples.
export function sample(traj, t) {
  const times = traj.times;
  const n = times.length;
  let k = 0;
  if (t >= times[n - 1]) k = n - 2;
  else {
    let lo = 0, hi = n - 1;
    while (hi - lo > 1) {
      const mid = (lo + hi) >> 1;
      if (times[mid] <= t) lo = mid; else hi = mid;
    }
    k = lo;
  }
  k = Math.max(0, Math.min(k, n - 2));
  const t0 = times[k], t1 = times[Math.min(k + 1, n - 1)];
  const a = t1 > t0 ? Math.min(1, Math.max(0, (t - t0) / (t1 - t0))) : 0;
  const positions = {}, velocities = {};
  traj.joints.forEach((name, j) => {
    const p0 = traj.positions[k][j], p1 = traj.positions[Math.min(k + 1, n - 1)][j];
    const v0 = traj.velocities[k][j], v1 = traj.velocities[Math.min(k + 1, n - 1)][j];
    positions[name] = p0 + a * (p1 - p0);
    velocities[name] = v0 + a * (v1 - v0);
  });
  return { positions, velocities };
}
