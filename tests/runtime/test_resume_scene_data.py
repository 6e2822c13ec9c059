"""One JSON form of a scene's objects (:mod:`taskrunner.runtime.replay`): exact in a
checkpoint, read back as it was; rounded for a viewer, a mesh by its file name."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from taskrunner.errors import InputError
from taskrunner.runtime.replay import object_data, object_of, shape_of
from taskrunner.scene.objects import SceneObject
from taskrunner.shapes import Box, Cylinder, Mesh, Sphere
from taskrunner.types import Pose

POSE = Pose((0.1234567891, -0.2, 0.7700000123), (0.0, 0.0, 0.1986693308, 0.9800665778))
OBJECTS = [
    SceneObject("box", Box((0.04, 0.05, 0.06)), POSE),
    SceneObject("can", Cylinder(0.03, 0.12), POSE),
    SceneObject("ball", Sphere(0.021), POSE),
    SceneObject("part", Mesh(Path("/data/meshes/part.stl"), (0.001, 0.001, 0.002)), POSE),
    SceneObject("held", Box((0.025, 0.025, 0.025)), Pose((0.0, 0.0, 0.1), frame="tool0"),
                attached_to="tool0", touch_links=("finger_l", "finger_r")),
]


@pytest.mark.parametrize("obj", OBJECTS, ids=[o.name for o in OBJECTS])
def test_a_checkpoints_object_reads_back_as_it_was(obj):
    data = json.loads(json.dumps(object_data(obj, exact=True)))  # as a journal keeps it
    assert object_of(data) == obj


def test_a_viewers_object_is_rounded_and_names_a_mesh_by_its_file_only():
    data = object_data(OBJECTS[3])
    assert data["shape"] == {"type": "mesh", "file": "part.stl", "scale": [0.001, 0.001, 0.002]}
    assert data["pose"]["xyz"] == [0.123457, -0.2, 0.77] and "touch_links" not in data


def test_an_unknown_shape_type_is_refused_naming_the_field():
    with pytest.raises(InputError, match=r"'shape.type' must be box, cylinder, sphere or "
                                         r"mesh \(got 'cone'\)"):
        shape_of({"type": "cone", "radius": 0.1})
