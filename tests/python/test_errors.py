"""Bad input raises the library's exception with the message the command line prints
(file, line, key, expected vs found), as a subclass of the Python error a caller expects."""
import re

import pytest

import tribo


def test_missing_file():
    with pytest.raises(tribo.SceneError, match="no_such_scene.yaml") as e:
        tribo.load_scene("no_such_scene.yaml")
    assert isinstance(e.value, ValueError) and isinstance(e.value, tribo.Error)


def test_bad_key_names_file_line_and_key():
    text = "simulation:\n  duration: 1\n  time_step: -0.001\n"
    with pytest.raises(tribo.SceneError) as e:
        tribo.load_scene(text)
    err = e.value
    assert err.file == "<string>" and err.line == 3
    assert "time_step" in err.key and "time_step" in str(err)
    assert str(err).startswith("<string>:3:")


def test_unknown_override(belt):
    with pytest.raises(tribo.SceneError, match="no_such_parameter"):
        tribo.load_scene(belt, set={"no_such_parameter": 1})
    with pytest.raises(TypeError):
        tribo.load_scene(belt, set={"v_b": [1, 2]})


def test_overrides_cross_exactly(belt):
    v = 0.1 + 0.2  # 0.30000000000000004: needs all 17 digits
    scene = tribo.load_scene(belt, set={"v_b": v, "integrator": "semi_implicit_euler",
                                        "duration": 2})
    assert float(scene.parameters["v_b"]) == v
    assert scene.settings["integrator"] == "semi_implicit_euler"
    assert scene.settings["duration"] == 2.0


def test_scene_description(belt):
    scene = tribo.load_scene(belt)
    assert [b["name"] for b in scene.bodies] == ["belt", "box"]
    assert scene.bodies[1]["mass"] == 10.0 and scene.bodies[0]["kind"] == "kinematic"
    assert scene.joints == [{"name": "box_on_belt", "type": "planar_translation",
                             "parent": "world", "child": "box"}]
    assert scene.columns[0] == "t" and "box.x" in scene.columns


def test_bad_urdf(tmp_path):
    bad = tmp_path / "bad.urdf"
    bad.write_text("<robot name='r'><link name='a'/><joint name='j' type='revolute'>"
                   "<parent link='a'/><child link='missing'/></joint></robot>")
    with pytest.raises(tribo.Error, match="missing"):
        tribo.load_urdf(bad)


def test_urdf_robot_runs(source_dir):
    robots = sorted((source_dir / "scenes" / "robots").rglob("*.urdf"))
    assert robots, "no URDF robot in scenes/robots"
    scene = tribo.load_urdf(robots[0], set={"duration": 0.05})
    result = scene.run()
    assert result.status == "complete"
    assert len(result["t"]) > 1


def test_parameters_come_back_as_numbers(belt):
    scene = tribo.load_scene(belt, set={"v_b": 0.7})
    p = scene.parameters
    assert p["v_b"] == 0.7 and isinstance(p["v_b"], float)
    assert p["m"] == 10.0
    assert p["friction"] == "roh_yoo"  # a word stays text
    assert isinstance(p["z0"], str) and "$m" in p["z0"]  # an expression, as written


@pytest.mark.parametrize("setting,value", [("duration", "10"), ("time_step", None.__class__),
                                           ("output_interval", [0.1]), ("duration", True),
                                           ("relative_tolerance", "1e-6")])
def test_run_settings_of_the_wrong_type_name_the_argument(belt, setting, value):
    with pytest.raises(TypeError, match=f"run: {setting} must be a number"):
        tribo.load_scene(belt).run(**{setting: value})


def test_version(source_dir):
    major, minor, patch = (int(x) for x in tribo.__version__.split("."))
    assert (major, minor, patch) >= (0, 1, 0)
    # The one version number: the CMake project's (top-level CMakeLists.txt).
    project = re.search(r"^project\(tribo VERSION ([0-9.]+)",
                        (source_dir / "CMakeLists.txt").read_text(), re.MULTILINE)
    assert project, "no project(tribo VERSION ...) in CMakeLists.txt"
    assert tribo.__version__ == project.group(1)
