"""Bad input raises the library's exception with the message the command line prints
(file, line, key, expected vs found), as a subclass of the Python error a caller expects."""
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
