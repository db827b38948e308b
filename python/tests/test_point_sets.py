# SPDX-License-Identifier: GPL-3.0-or-later
"""point_set_curvatures: the library's estimator over an (n, 3) array, on a sphere of radius 2."""

import numpy as np
import pytest

import curvature_estimation as ce

RADIUS = 2.0


def sphere_points(n=2000):
    """Fibonacci points on the sphere of radius RADIUS, and their outward normals."""
    k = np.arange(n) + 0.5
    z = 1 - 2 * k / n
    phi = np.pi * (1 + 5 ** 0.5) * k
    normals = np.column_stack([np.sqrt(1 - z * z) * np.cos(phi), np.sqrt(1 - z * z) * np.sin(phi), z])
    return RADIUS * normals, normals


@pytest.mark.parametrize("kwargs", [{}, {"fit_degree": 3}, {"number_of_neighbors": 24},
                                    {"neighbor_radius": 0.3}, {"threads": 1}], ids=str)
def test_sphere_with_outward_normals(kwargs):
    points, normals = sphere_points()
    r = ce.point_set_curvatures(points, normals=normals, **kwargs)
    assert r._fields == ("k_max", "k_min", "mean", "gaussian", "d_max", "d_min", "status", "normal")
    assert r.status.dtype == np.uint8 and np.all(r.status != ce.Status.failed)
    np.testing.assert_allclose(r.mean, 1 / RADIUS, rtol=1e-2)
    np.testing.assert_allclose(r.gaussian, 1 / RADIUS ** 2, rtol=2e-2)
    assert np.all(r.k_max >= r.k_min)
    np.testing.assert_allclose(np.abs(np.sum(r.normal * normals, axis=1)), 1, atol=1e-3)
    np.testing.assert_allclose(np.abs(np.sum(r.d_max * normals, axis=1)), 0, atol=1e-3)


def test_orientation_without_normals_and_unsigned():
    points, _ = sphere_points()
    oriented = ce.point_set_curvatures(points)
    # one consistent orientation over the sphere (outward on the whole): one sign of H
    assert np.all(np.sign(oriented.mean) == np.sign(oriented.mean[0]))
    np.testing.assert_allclose(np.abs(oriented.mean), 1 / RADIUS, rtol=1e-2)
    flipped = ce.point_set_curvatures(points, normals=-sphere_points()[1])
    assert np.all(flipped.mean < 0)
    unsigned = ce.point_set_curvatures(points, normals=None, unsigned=True)
    assert np.all(unsigned.mean > 0)


def test_threads_give_the_same_values():
    points, _ = sphere_points(500)
    one = ce.point_set_curvatures(points, threads=1)
    every = ce.point_set_curvatures(points, threads=0)
    for a, b in zip(one, every):
        np.testing.assert_array_equal(a, b)
