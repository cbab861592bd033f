"""What the Python benchmark scripts share: the default mesh (the Spot refinement cc3 of the
shared data when it sits next to the checkout, else the bundled cc1) and uniform points in
a mesh's bounding box grown by 5% per side."""
import os

import numpy as np

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SHARED_SPOT = os.path.join(HERE, "..", "shared", "data", "meshes", "spot", "spot_quad_cc3.ply")
BUNDLED_SPOT = os.path.join(HERE, "tests", "data", "meshes", "spot", "spot_quad_cc1.ply")


def default_spot() -> str:
    return SHARED_SPOT if os.path.exists(SHARED_SPOT) else BUNDLED_SPOT


def box_points(mesh, count: int, rng: np.random.Generator) -> np.ndarray:
    """count points uniform in the box of mesh.vertices grown by 5% per side."""
    lower, upper = mesh.vertices.min(axis=0), mesh.vertices.max(axis=0)
    grow = 0.05 * (upper - lower)
    return rng.uniform(lower - grow, upper + grow, (count, 3))
