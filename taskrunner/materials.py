"""What an object is made of, for a physics simulation: mass (or density) and friction.

Cell objects and task objects may say ``mass`` (kg), ``density`` (kg/m³, the mass then
follows from the shape's volume) and ``friction`` (one sliding coefficient, or sliding,
torsional and rolling as MuJoCo takes them). Only the ``mujoco`` backend uses them; the
kinematic backends (mock, sim) and the servos ignore them. :class:`Material` is the
plain result, free of any simulator.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Annotated, Any

from pydantic import AfterValidator, BeforeValidator, Field, WithJsonSchema

from taskrunner.errors import ArgumentError
from taskrunner.validation import NUMBER, check_number

__all__ = ["Density", "Friction", "Kilograms", "Material", "check_material", "material_of"]

MAX_KILOGRAMS = 1e4
MAX_DENSITY = 1e5  # kg/m^3 (osmium is 22 600)
MAX_FRICTION = 100.0


def _bounded(low: float, high: float, unit: str, low_open: bool) -> Any:
    def check(value: float) -> float:
        problem = check_number(value, low, high, unit, low_open)
        if problem is not None:
            raise ArgumentError(problem)
        return value
    return AfterValidator(check)


Kilograms = Annotated[float, NUMBER, _bounded(0.0, MAX_KILOGRAMS, "kg", True),
                      Field(json_schema_extra={"exclusiveMinimum": 0, "maximum": MAX_KILOGRAMS})]
"""A mass (kg): finite, > 0."""
Density = Annotated[float, NUMBER, _bounded(0.0, MAX_DENSITY, "kg/m³", True),
                    Field(json_schema_extra={"exclusiveMinimum": 0, "maximum": MAX_DENSITY})]
"""A density (kg/m³): finite, > 0."""
Coefficient = Annotated[float, NUMBER, _bounded(0.0, MAX_FRICTION, "", False),
                        Field(json_schema_extra={"minimum": 0, "maximum": MAX_FRICTION})]
_COEFFICIENT_SCHEMA = {"type": "number", "minimum": 0, "maximum": MAX_FRICTION}
Friction = Annotated[
    list[Coefficient], Field(min_length=1, max_length=3),
    BeforeValidator(lambda v: [v] if isinstance(v, (int, float)) and not isinstance(v, bool)
                    else v),
    WithJsonSchema({"anyOf": [_COEFFICIENT_SCHEMA, {"type": "array", "items": _COEFFICIENT_SCHEMA,
                                                    "minItems": 1, "maxItems": 3}]})]
"""Friction: a sliding coefficient, or [sliding, torsional, rolling] (each finite, ≥ 0)."""


@dataclass(frozen=True)
class Material:
    """The physics an object's file gave (None: the simulator's default).

    Attributes:
        mass: kg (wins over ``density``).
        density: kg/m³.
        friction: sliding, then torsional and rolling if given (1 to 3 numbers).
    """

    mass: float | None = None
    density: float | None = None
    friction: tuple[float, ...] | None = None

    def __bool__(self) -> bool:
        return not (self.mass is None and self.density is None and self.friction is None)


def material_of(spec: Any) -> Material:
    """The :class:`Material` of a validated object spec (cell or task) with optional
    ``mass``, ``density`` and ``friction`` fields."""
    friction = getattr(spec, "friction", None)
    if friction is not None:
        friction = tuple(float(f) for f in friction)
    return Material(getattr(spec, "mass", None), getattr(spec, "density", None), friction)


def check_material(spec: Any) -> None:
    """Raise ``ValueError`` if an object spec gives both ``mass`` and ``density``."""
    if getattr(spec, "mass", None) is not None and getattr(spec, "density", None) is not None:
        raise ArgumentError("give 'mass' or 'density', not both (the mass of a shape of a "
                         "given density follows from its volume)")
