"""Write the disabled collision pairs of a benchmark robot's SRDF, as MoveIt's setup
assistant chooses them: pairs of links joined by a joint ("Adjacent"), links that never
move relative to each other ("Rigid": no moving joint between them), pairs in contact in
the ready state ("Default") and pairs in contact in more than 95 % of seeded random states
within the limits ("Always"). Pairs that merely never met in sampling are *not* disabled
(the setup assistant's "Never"), so every pair that can touch stays checked.

    python benchmarks/robots/make_srdf.py benchmarks/robots/tiago/tiago.urdf \
        --group arm_torso --base base_footprint --tip tiago_tcp \
        --ready torso_lift_joint=0.15,arm_1_joint=0.2,... [--samples 1000] > tiago.srdf

The URDF's ``package://`` meshes are found in example-robot-data's share folder and in
``benchmarks/robots``.
"""

from __future__ import annotations

import argparse
import itertools
import sys
import warnings
import xml.etree.ElementTree as ET
from pathlib import Path

import coal
import numpy as np
import pinocchio as pin

ROBOTS = Path(__file__).resolve().parent
sys.path.insert(0, str(ROBOTS.parents[1]))

from taskrunner.robot.packages import example_robot_data_dir


def _moving_parent(model: pin.Model, frame: int) -> int:
    return int(model.frames[frame].parentJoint)


def disabled_pairs(urdf: Path, ready: dict[str, float], samples: int, seed: int = 0
                   ) -> dict[frozenset[str], str]:
    share = example_robot_data_dir()
    dirs = [str(ROBOTS)] + ([str(share.parent)] if share is not None else [])
    model = pin.buildModelFromUrdf(str(urdf))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        geom = pin.buildGeomFromUrdf(model, str(urdf), pin.COLLISION, dirs)
    links = [model.frames[g.parentFrame].name for g in geom.geometryObjects]
    joint_of = {links[i]: int(g.parentJoint) for i, g in enumerate(geom.geometryObjects)}
    pairs: dict[frozenset[str], str] = {}
    for a, b in itertools.combinations(sorted(set(links)), 2):
        if joint_of[a] == joint_of[b]:
            pairs[frozenset((a, b))] = "Rigid"
    for joint in ET.parse(urdf).getroot().findall("joint"):
        parent, child = joint.find("parent"), joint.find("child")
        if parent is None or child is None:
            continue
        a, b = parent.get("link"), child.get("link")
        if a in joint_of and b in joint_of and a != b:
            pairs[frozenset((a, b))] = "Adjacent"
    data = model.createData()
    geom.addAllCollisionPairs()
    gdata = pin.GeometryData(geom)

    def touching(q: np.ndarray) -> set[frozenset[str]]:
        pin.updateGeometryPlacements(model, data, geom, gdata, q)
        found = set()
        for cp in geom.collisionPairs:
            key = frozenset((links[cp.first], links[cp.second]))
            if len(key) < 2 or key in pairs or key in found:
                continue
            ta, tb = gdata.oMg[cp.first], gdata.oMg[cp.second]
            if coal.collide(geom.geometryObjects[cp.first].geometry,
                            coal.Transform3s(ta.rotation, ta.translation),
                            geom.geometryObjects[cp.second].geometry,
                            coal.Transform3s(tb.rotation, tb.translation),
                            coal.CollisionRequest(), coal.CollisionResult()):
                found.add(key)
        return found

    q_ready = pin.neutral(model)
    for name, value in ready.items():
        q_ready[model.joints[model.getJointId(name)].idx_q] = value
    for key in touching(q_ready):
        pairs[key] = "Default"
    rng = np.random.default_rng(seed)
    lower = np.maximum(model.lowerPositionLimit, -np.pi)
    upper = np.minimum(model.upperPositionLimit, np.pi)
    counts: dict[frozenset[str], int] = {}
    for _ in range(samples):
        for key in touching(rng.uniform(lower, upper)):
            counts[key] = counts.get(key, 0) + 1
    for key, n in counts.items():
        if n > 0.95 * samples:
            pairs[key] = "Always"
    return pairs


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("urdf", type=Path)
    parser.add_argument("--name", required=True, help="the robot's name in the SRDF")
    parser.add_argument("--group", required=True)
    parser.add_argument("--base", required=True, help="the group chain's base link")
    parser.add_argument("--tip", required=True, help="the group chain's tip link")
    parser.add_argument("--ready", required=True, help="joint=value,... of the ready state")
    parser.add_argument("--samples", type=int, default=1000)
    args = parser.parse_args(argv)
    ready = {k: float(v) for k, v in (item.split("=") for item in args.ready.split(","))}
    pairs = disabled_pairs(args.urdf, ready, args.samples)
    out = ['<?xml version="1.0"?>',
           f"<!-- Written by benchmarks/robots/make_srdf.py ({args.samples} samples, seed 0) -->",
           f'<robot name="{args.name}">',
           f'  <group name="{args.group}">',
           f'    <chain base_link="{args.base}" tip_link="{args.tip}"/>',
           "  </group>",
           f'  <group_state name="ready" group="{args.group}">']
    out += [f'    <joint name="{k}" value="{v}"/>' for k, v in ready.items()]
    out.append("  </group_state>")
    for key, reason in sorted(pairs.items(), key=lambda kv: sorted(kv[0])):
        a, b = sorted(key)
        out.append(f'  <disable_collisions link1="{a}" link2="{b}" reason="{reason}"/>')
    out.append("</robot>")
    print("\n".join(out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
