"""A MujocoWorld's cameras as NumPy arrays (rtamp.Camera, docs/python.md), checked
against what the scene is: the blocks' colour where the segmentation pass says a
block is, the point cloud on the table top and on the blocks' tops, the camera
matrix projecting a block's centre into its pixels; scenario colours; and a world
perceiving through several cameras (overhead and wrist) into one belief."""

import numpy as np
import pytest

import rtamp


def test_a_frame_is_numpy_arrays_of_the_cameras_shape(tray):
    w = rtamp.MujocoWorld(tray, seed=1)
    cam = rtamp.Camera(w)  # the primary camera: overhead
    assert cam.name == "overhead"
    width, height = cam.resolution
    f = cam.render(segmentation=True)
    assert f.camera == "overhead"
    assert f.rgb.shape == (height, width, 3) and f.rgb.dtype == np.uint8
    assert f.depth.shape == (height, width) and f.depth.dtype == np.float32
    assert f.segmentation.shape == (height, width) and f.segmentation.dtype == np.int32
    assert f.K.shape == (3, 3) and f.world_to_camera.shape == (4, 4)
    np.testing.assert_allclose(f.K, cam.K)
    assert cam.render().segmentation is None
    # Arrays are copies: a later frame does not change an earlier one.
    before = f.rgb.copy()
    cam.render()
    np.testing.assert_array_equal(f.rgb, before)


def test_pixels_and_points_agree_with_the_scene(tray):
    w = rtamp.MujocoWorld(tray, seed=1)
    f = rtamp.Camera(w).render(segmentation=True, noise=False)
    seen = f.segmentation >= 0
    assert seen.mean() > 0.5  # the table fills most of the picture
    # The blocks are red (class colour of "block"): the pixels of the bodies the
    # segmentation pass shows most red are red-dominant.
    red = (f.rgb[..., 0].astype(int) - np.maximum(f.rgb[..., 1], f.rgb[..., 2]).astype(int)) > 60
    assert red.sum() > 100
    red_bodies = np.unique(f.segmentation[red])
    assert 1 <= len(red_bodies) <= 3
    # The point cloud: every pixel with a reading, in the world; the table top (z = 0)
    # is the commonest height, and the blocks' tops stand 4 cm above it.
    pts = f.points()
    assert pts.shape == (int((f.depth > 0).sum()), 3)
    z = pts[:, 2]
    assert np.median(np.abs(z[np.abs(z) < 0.01])) < 0.002
    block_pts = pts[red[f.depth > 0]]
    assert np.median(block_pts[:, 2]) == pytest.approx(0.04, abs=0.006)
    # K and world_to_camera project the blocks' points back into their own pixels.
    h = np.c_[block_pts, np.ones(len(block_pts))] @ f.world_to_camera.T
    uv = (h[:, :3] @ f.K.T)
    uv = uv[:, :2] / uv[:, 2:3]
    rows, cols = np.nonzero(red & (f.depth > 0))
    np.testing.assert_allclose(uv[:, 0], cols, atol=1e-3)
    np.testing.assert_allclose(uv[:, 1], rows, atol=1e-3)


def test_an_unknown_camera_is_an_error(tray):
    w = rtamp.MujocoWorld(tray, seed=1)
    with pytest.raises(rtamp.Error, match="unknown camera 'ceiling'"):
        rtamp.Camera(w, "ceiling")
    assert rtamp.Camera(w, "wrist").resolution == (424, 240)


def test_colours_of_classes(tray):
    s = tray.copy()
    assert s.colours == {}
    s.colours = {"block": (0.1, 0.2, 0.9)}
    back = rtamp.parse_scenario(s.to_yaml())
    assert back.colours == {"block": pytest.approx((0.1, 0.2, 0.9))}
    f = rtamp.Camera(rtamp.MujocoWorld(back, seed=1)).render(noise=False)
    blue = (f.rgb[..., 2].astype(int) - np.maximum(f.rgb[..., 0], f.rgb[..., 1]).astype(int)) > 60
    assert blue.sum() > 100
    s.colours = {"cup": (1, 0, 0)}
    with pytest.raises(rtamp.Error, match="unknown class 'cup'"):
        s.validate()
    s.colours = {"block": (0.56, 0.37, 0.2)}  # the trays' wood: the trays' default colour moves away
    rtamp.MujocoWorld(s, perception="camera")
    s.colours = {"block": (0.56, 0.37, 0.2), "tray": (0.57, 0.38, 0.21)}  # two of the user's own alike
    s.validate()  # fine for the truth ...
    with pytest.raises(rtamp.Error, match="look alike to the camera"):
        rtamp.MujocoWorld(s, perception="camera")  # ... not for the camera


def test_several_cameras_perceive_into_one_belief(tray):
    w = rtamp.MujocoWorld(tray, seed=1, perception="camera", cameras=["overhead", "wrist"])
    assert w.observe() == rtamp.initial_placement(tray)
    with pytest.raises(rtamp.Error, match="unknown camera 'ceiling'"):
        rtamp.MujocoWorld(tray, perception="camera", cameras=["ceiling"])
    with pytest.raises(rtamp.Error, match="only with perception='camera'"):
        rtamp.MujocoWorld(tray, cameras=["wrist"])
