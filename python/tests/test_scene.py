"""Scenes: load (JSON and pbrt-v4), to_dict and from_dict round trips, edits that change the image."""
import numpy as np
import pytest

import candela
from conftest import CORNELL, CORNELL_PBRT, tiny_document


def test_load_json_gives_the_files_document(cornell):
    import json
    assert cornell.to_dict() == json.loads(CORNELL.read_text())
    assert cornell.file == str(CORNELL)


def test_round_trip_renders_the_same_bits(cornell):
    again = candela.Scene.from_dict(cornell.to_dict(), folder=CORNELL.parent)
    a = candela.render(cornell, spp=2, resolution=(24, 16), threads=2)
    b = candela.render(again, spp=2, resolution=(24, 16), threads=2)
    assert np.array_equal(a, b)


def test_an_edit_changes_the_image_and_only_the_copy(cornell):
    d = cornell.to_dict()
    d["materials"]["white"]["albedo"] = [0.2, 0.2, 0.2]
    darker = candela.Scene.from_dict(d, like=cornell)
    assert cornell.to_dict()["materials"]["white"]["albedo"] == [0.725, 0.71, 0.68]
    a = candela.render(cornell, spp=2, resolution=(24, 16), threads=2)
    b = candela.render(darker, spp=2, resolution=(24, 16), threads=2)
    assert b.mean() < 0.9 * a.mean()


def test_the_documents_values_round_trip_exactly():
    d = tiny_document()
    d["sampler"]["seed"] = 2**64 - 1
    d["camera"]["fov"] = 0.1 + 0.2  # a double that a float or a short decimal would change
    assert candela.Scene.from_dict(d).to_dict() == d


def test_numpy_values_and_tuples_are_taken():
    d = tiny_document(albedo=np.float32(0.25))
    d["camera"]["position"] = np.array([0.0, 0.0, -4.0])
    d["camera"]["resolution"] = (8, 6)
    back = candela.Scene.from_dict(d).to_dict()
    assert back["materials"]["m"]["albedo"] == 0.25
    assert back["camera"]["position"] == [0.0, 0.0, -4.0]
    assert back["camera"]["resolution"] == [8, 6]


def test_a_value_no_document_holds_is_a_type_error_with_its_pointer():
    d = tiny_document()
    d["materials"]["m"]["albedo"] = {0.5}
    with pytest.raises(TypeError, match="/materials/m/albedo"):
        candela.Scene.from_dict(d)


def test_pbrt_scene_loads_edits_and_keeps_its_meshes():
    scene = candela.load(CORNELL_PBRT)
    d = scene.to_dict()
    assert d["integrator"]["spectral"] is True  # pbrt-v4 scenes render spectrally
    a = candela.render(scene, spp=1, resolution=(16, 16), threads=2)
    same = candela.render(candela.Scene.from_dict(d, like=scene), spp=1, resolution=(16, 16), threads=2)
    assert np.array_equal(a, same)
    for material in d["materials"].values():
        if "albedo" in material:
            material["albedo"] = 0.1
    darker = candela.render(candela.Scene.from_dict(d, like=scene), spp=1, resolution=(16, 16), threads=2)
    assert darker.mean() < 0.8 * a.mean()


def test_relative_files_resolve_against_the_folder(tmp_path):
    d = candela.load(CORNELL).to_dict()
    with pytest.raises(candela.SceneError, match="meshes/white_walls.obj"):
        candela.Scene.from_dict(d, folder=tmp_path)
    assert candela.Scene.from_dict(d, folder=CORNELL.parent).file is None
