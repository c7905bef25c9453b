"""Errors: SceneError carries the file, line, column and JSON pointer the CLI prints."""
import pytest

import candela
from conftest import BAD_INPUTS, run_cli, tiny_document

# A few of the bad-input corpus's files (tests/data/bad_inputs): JSON and pbrt-v4, in the scene
# file itself and in a file it names.
CORPUS = ["albedo_out_of_range.json", "boolean_for_number.json", "blend_cycle.json", "aov_unknown.json",
          "pbrt_unknown_directive.pbrt", "pbrt_unterminated_string.pbrt", "mesh_empty_ply.json"]


@pytest.mark.parametrize("name", [n for n in CORPUS if (BAD_INPUTS / n).exists()])
def test_load_raises_the_clis_error_line(name):
    cli = run_cli("render", BAD_INPUTS / name, "-o", "/dev/null/never.png", check=False)
    assert cli.returncode == 2
    with pytest.raises(candela.SceneError) as raised:
        candela.load(BAD_INPUTS / name)
    assert f"candela: error: {raised.value}" == cli.stderr.strip().splitlines()[-1]


def test_the_corpus_names_above_exist():
    assert sum((BAD_INPUTS / n).exists() for n in CORPUS) >= 5


def test_attributes_locate_the_problem(tmp_path):
    scene = tmp_path / "scene.json"
    scene.write_text('{\n  "materials": {\n    "m": {"type": "diffuse", "albdo": 0.5}\n  }\n}\n')
    with pytest.raises(candela.SceneError) as raised:
        candela.load(scene)
    e = raised.value
    assert isinstance(e, ValueError)
    assert (e.file, e.line, e.column, e.pointer) == (str(scene), 3, 30, "/materials/m")
    assert e.message == 'unknown key "albdo" (did you mean "albedo"?)'
    assert str(e) == f'{scene}:3:30: /materials/m: unknown key "albdo" (did you mean "albedo"?)'


def test_a_dicts_error_is_located_by_its_pointer():
    d = tiny_document()
    d["shapes"][0]["radius"] = -1
    with pytest.raises(candela.SceneError) as raised:
        candela.Scene.from_dict(d)
    e = raised.value
    assert (e.file, e.line, e.pointer) == ("", 0, "/shapes/0/radius")
    assert str(e).startswith("/shapes/0/radius: ")


def test_a_missing_file():
    with pytest.raises(candela.SceneError, match="scene file not found") as raised:
        candela.load("no/such/scene.json")
    assert raised.value.file == "no/such/scene.json"


@pytest.mark.parametrize("keywords, words", [
    ({"spp": 0}, "spp: expected an integer >= 1, got 0"),
    ({"resolution": (0, 4)}, "resolution: "),
    ({"aovs": ["albedo", "colour"]}, 'aovs: unknown AOV layer "colour"'),
    ({"integrator": "pathh"}, 'integrator: unknown integrator "pathh"'),
    ({"threads": -1}, "threads: expected an integer >= 0, got -1"),
    ({"time_limit": 0.0}, "time_limit: expected seconds > 0, got 0"),
    ({"target_error": -1.0}, "target_error: "),
])
def test_bad_keywords_are_scene_errors(keywords, words):
    scene = candela.Scene.from_dict(tiny_document())
    with pytest.raises(candela.SceneError) as raised:
        candela.render(scene, **keywords)
    assert str(raised.value).startswith(words)  # named by the keyword, not the CLI's flag


def test_bad_image_files(tmp_path):
    bad = tmp_path / "bad.exr"
    bad.write_bytes(b"not an exr")
    with pytest.raises(candela.SceneError) as raised:
        candela.read(bad)
    assert raised.value.file == str(bad)
    with pytest.raises(candela.SceneError, match="unknown image extension"):
        candela.write([[[0, 0, 0]]], tmp_path / "x.tiff")
    with pytest.raises(ValueError, match="shape"):
        candela.write([1, 2, 3], tmp_path / "x.exr")
