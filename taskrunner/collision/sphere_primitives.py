"""Conservative sphere sets of coal's primitive solids (boxes, spheres, cylinders,
capsules), for :mod:`taskrunner.collision.spheres`; every point of the solid is covered by
construction:

* a box: a grid of cells, each inside the sphere through its corners (the grid is refined
  until the looseness is within the tolerance, or the next grid would pass ``max_spheres``);
* a cylinder: the same over its box, keeping the cells that meet it; one cell wide, spheres
  on its axis through the rims of their slabs;
* a capsule: spheres on its axis, radius R' every s with R'^2 = R^2 + (s/2)^2 (a point of
  the capsule is within s/2 along the axis of a centre, and within R of the axis);
* a sphere: itself.

The looseness (how far the union reaches outside the solid, m) is measured in closed form at
:data:`BOUNDARY_POINTS` points per sphere on the union's surface.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["BOUNDARY_POINTS", "GROW", "fit_primitive", "primitive_distance", "union_surface"]

BOUNDARY_POINTS = 96  # looseness probes per sphere
GROW = 1e-9  # m, on every radius: float rounding never uncovers a corner


def fit_primitive(kind: str, dims: tuple[float, ...], tolerance: float, max_spheres: int
                  ) -> tuple[np.ndarray, np.ndarray, float]:
    """Spheres (centres (n, 3), radii) containing the solid, and its looseness (m).

    Args:
        kind: ``box`` (``dims``: half extents), ``sphere`` (radius), ``cylinder`` or
            ``capsule`` (radius, half length; about z).
        tolerance: the looseness to aim for (m).
        max_spheres: at most this many spheres.
    """
    if kind == "sphere":
        return np.zeros((1, 3)), np.array([dims[0] * (1 + 1e-9) + GROW]), 0.0
    if kind == "capsule":  # spheres of radius R' every s: R'^2 = R^2 + (s/2)^2 covers between
        radius, half = dims
        gap = math.sqrt((radius + tolerance) ** 2 - radius ** 2)
        if max_spheres < 2:  # one sphere around it all
            centre, radius_all = np.zeros((1, 3)), np.array([(radius + half) * (1 + 1e-9) + GROW])
            return centre, radius_all, _looseness(kind, dims, centre, radius_all)
        n = max(1, min(max_spheres - 1, math.ceil(half / gap)))
        z = np.linspace(-half, half, n + 1)
        centres = np.column_stack([np.zeros(n + 1), np.zeros(n + 1), z])
        radii = np.full(n + 1, math.hypot(radius, half / n) * (1 + 1e-9) + GROW)
        return centres, radii, _looseness(kind, dims, centres, radii)
    halves = np.array((dims[0], dims[0], dims[1]) if kind == "cylinder" else dims)
    best: tuple[np.ndarray, np.ndarray, float] | None = None
    edge = max(2 * float(halves.max()), 1e-9)
    while True:
        fit = _grid(kind, halves, dims, edge)
        if len(fit[1]) > max_spheres and best is not None:
            return best
        looseness = _looseness(kind, dims, *fit)
        if best is None or looseness < best[2]:
            best = (*fit, looseness)
        if looseness <= tolerance:
            return best
        edge *= 0.85


def _grid(kind: str, half: np.ndarray, dims: tuple[float, ...], edge: float
          ) -> tuple[np.ndarray, np.ndarray]:
    """Cells of about ``edge`` over the solid's box that meet the solid, each in the sphere
    through its corners (a cylinder one cell wide: spheres on its axis through its rims)."""
    counts = np.maximum(1, np.ceil(2 * half / edge - 1e-9)).astype(int)
    cell = 2 * half / counts
    axes = [-half[i] + cell[i] * (np.arange(counts[i]) + 0.5) for i in range(3)]
    grid = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)
    radius = float(np.linalg.norm(cell)) / 2
    if kind == "cylinder" and counts[0] == 1:
        radius = math.hypot(dims[0], cell[2] / 2)
    elif kind == "cylinder":  # keep the cells whose square meets the disk
        gap = np.maximum(np.abs(grid[:, :2]) - cell[:2] / 2, 0.0)
        grid = grid[np.hypot(gap[:, 0], gap[:, 1]) <= dims[0]]
    return grid, np.full(len(grid), radius * (1 + 1e-9) + GROW)


def _looseness(kind: str, dims: tuple[float, ...], centres: np.ndarray,
                     radii: np.ndarray) -> float:
    probes = union_surface(centres, radii)
    return float(max(0.0, primitive_distance(kind, dims, probes).max(initial=0.0)))


def primitive_distance(kind: str, dims: tuple[float, ...], p: np.ndarray) -> np.ndarray:
    """Signed distance (m) from points to the solid (negative inside)."""
    if kind == "sphere":
        return np.linalg.norm(p, axis=1) - dims[0]
    if kind == "capsule":
        z = np.clip(p[:, 2], -dims[1], dims[1])
        return np.linalg.norm(p - np.column_stack([0 * z, 0 * z, z]), axis=1) - dims[0]
    if kind == "cylinder":
        d = np.column_stack([np.hypot(p[:, 0], p[:, 1]) - dims[0], np.abs(p[:, 2]) - dims[1]])
    else:
        d = np.abs(p) - np.array(dims)
    return np.linalg.norm(np.maximum(d, 0.0), axis=1) + np.minimum(d.max(axis=1), 0.0)


def _unit_sphere(n: int) -> np.ndarray:
    """``n`` points spread evenly on the unit sphere (a Fibonacci lattice)."""
    i = np.arange(n) + 0.5
    z = 1 - 2 * i / n
    phi = math.pi * (1 + math.sqrt(5)) * i
    s = np.sqrt(1 - z * z)
    return np.column_stack([s * np.cos(phi), s * np.sin(phi), z])


def union_surface(centres: np.ndarray, radii: np.ndarray) -> np.ndarray:
    """Points on the union's surface: each sphere's probes not inside another sphere."""
    unit = _unit_sphere(BOUNDARY_POINTS)
    out = []
    for j, (c, r) in enumerate(zip(centres, radii, strict=True)):
        p = c + r * unit
        d = np.linalg.norm(p[:, None, :] - centres[None], axis=2) - radii[None]
        d[:, j] = np.inf
        out.append(p[d.min(axis=1) >= -1e-9])
    return np.concatenate(out) if out else np.zeros((0, 3))
