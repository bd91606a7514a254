# SPDX-License-Identifier: BSD-3-Clause
"""Relighting numpy images in memory through the C++ Relighter."""

import threading

import numpy as np
import pytest

import bandlight


def image(h=37, w=53, c=3, seed=1):
    rng = np.random.default_rng(seed)
    return (rng.uniform(0, 4, (h, w, c))).astype(np.float32)


def test_relight_is_the_matrix_for_linear_methods():
    img = image()
    m = bandlight.illuminant_change_matrix("A", "D65", "band3")
    out = bandlight.relight(img, "A", "D65", "band3")
    assert out.dtype == np.float32 and out.shape == img.shape
    assert out is not img
    np.testing.assert_allclose(out, img.astype(np.float64) @ m.T, rtol=1e-6, atol=1e-6)
    # The input is left as it was.
    np.testing.assert_array_equal(img, image())


def test_shapes_layouts_and_dtypes_agree():
    r = bandlight.Relighter("F11", "D65", "cat02")
    img = image()
    ref = r.apply(img)
    np.testing.assert_array_equal(r.apply(img.reshape(-1, 3)), ref.reshape(-1, 3))
    np.testing.assert_array_equal(r(img.astype(np.float64)), ref)  # converted to float32
    fortran = np.asfortranarray(img)
    np.testing.assert_array_equal(r.apply(fortran), ref)
    strided = np.ascontiguousarray(img[:, ::-1])[:, ::-1]  # a negative-stride view
    np.testing.assert_array_equal(r.apply(strided), ref)
    np.testing.assert_array_equal(r.apply(img[0, 0]), ref[0, 0])  # one pixel, shape (3,)


def test_alpha_and_other_channels_pass_through():
    r = bandlight.Relighter("A", "D65", "bradford")
    rgba = image(c=5)
    out = r.apply(rgba)
    np.testing.assert_array_equal(out[..., 3:], rgba[..., 3:])
    np.testing.assert_array_equal(out[..., :3], r.apply(np.ascontiguousarray(rgba[..., :3])))


def test_out_and_in_place():
    r = bandlight.Relighter("A", "D65", "rootpoly")
    img = image()
    ref = r.apply(img)
    out = np.empty_like(img)
    assert r.apply(img, out=out) is out
    np.testing.assert_array_equal(out, ref)
    in_place = img.copy()
    r.apply(in_place, out=in_place)
    np.testing.assert_array_equal(in_place, ref)
    with pytest.raises(ValueError, match="out must be"):
        r.apply(img, out=np.empty((2, 2, 3), np.float32))
    with pytest.raises(ValueError, match="out must be"):
        r.apply(img, out=np.empty(img.shape, np.float64))
    with pytest.raises(ValueError, match="overlaps"):
        big = np.zeros(img.size + 3, np.float32)
        r.apply(big[3:].reshape(img.shape), out=big[:-3].reshape(img.shape))


@pytest.mark.parametrize("method", ["band3", "rootpoly", "metamer"])
def test_threads_give_the_same_pixels(method):
    r = bandlight.Relighter("F2", "D65", method)
    img = image(h=400, w=300)
    one = r.apply(img, threads=1)
    np.testing.assert_array_equal(r.apply(img, threads=2), one)
    np.testing.assert_array_equal(r.apply(img, threads=0), one)
    with pytest.raises(ValueError, match="threads"):
        r.apply(img, threads=-1)


def test_hard_pixels_give_finite_results():
    r = bandlight.Relighter("A", "D65", "band3")
    hard = np.array([[np.nan, 0, 0], [np.inf, np.inf, np.inf], [-np.inf, 1, 1],
                     [1e30, 1, 1], [0, 0, 0]], np.float32)
    out = r.apply(hard)
    assert np.isfinite(out).all()
    np.testing.assert_array_equal(out[4], [0, 0, 0])
    # NaN enters the matrix as -1e16, +Inf as +1e16 (docs/robustness.md).
    m = r.matrix
    np.testing.assert_allclose(out[0], m @ [-1e16, 0, 0], rtol=1e-6)


def test_the_gil_is_released():
    # Two Python threads re-lighting at once both make progress, and get the
    # same pixels as one at a time.
    r = bandlight.Relighter("A", "D65", "rootpoly")
    img = image(h=600, w=400)
    ref = r.apply(img, threads=1)
    results = [None, None]

    def work(i):
        results[i] = r.apply(img, threads=1)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for res in results:
        np.testing.assert_array_equal(res, ref)


def test_bad_images_are_refused():
    r = bandlight.Relighter("A", "D65")
    with pytest.raises(ValueError, match="R, G, B"):
        r.apply(np.zeros((4, 2), np.float32))
    with pytest.raises(ValueError, match="R, G, B"):
        r.apply(np.float32(1.0))
    with pytest.raises(ValueError):
        r.apply(np.array([["a", "b", "c"]]))


def test_relighter_properties():
    r = bandlight.Relighter("a", "d65", "Band3-WP", working_space="Lin-sRGB")
    assert (r.src, r.dst, r.method, r.working_space) == ("A", "D65", "band3-wp", "rec709")
    assert r.is_linear
    np.testing.assert_allclose(
        r.matrix, bandlight.illuminant_change_matrix("A", "D65", "band3-wp",
                                                     working_space="rec709"))
    assert not bandlight.Relighter("A", "D65", "rootpoly").is_linear
    with pytest.raises(ValueError):
        bandlight.Relighter("A", "D65", "spectral")
