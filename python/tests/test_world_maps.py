"""Maps with a world frame (ROS map_server YAML files; nav2's sandbox map from $PRIDE_DATA/ros):
Grid.resolution and Grid.origin, plan's start_world/goal_world keywords and the result's
path_world, and the one-line errors naming the keyword."""
import os

import numpy as np
import pytest

import pride

from conftest import shared_data


@pytest.fixture
def sandbox():
    """nav2's tb3_sandbox map_server map (skipped, with the reason, without PRIDE_DATA)."""
    return str(shared_data("ros/tb3_sandbox.yaml", "nav2's ROS map_server maps"))


def test_frame_properties(sandbox):
    g = pride.Grid.load(sandbox)
    assert (g.width, g.height) == (384, 384)
    assert g.resolution == 0.05
    assert g.origin == (-10.0, -10.0)
    plain = pride.Grid(np.zeros((3, 4)))
    assert plain.resolution is None and plain.origin is None


def test_plan_in_world_coordinates(sandbox):
    g = pride.Grid.load(sandbox)
    r = pride.plan(g, start_world=(-2.0, -0.5), goal_world=(-0.5, 0.5), algo="astar")
    assert r.feasible
    # The cells holding the points: x = floor((-2 + 10) / 0.05) = 160, row from the bottom
    # floor(9.5 / 0.05) = 190, y = 383 - 190 = 193.
    assert tuple(r.path[0]) == (160, 193)
    assert r.path_world.shape == (len(r.path), 2)
    assert tuple(r.path_world[0]) == (-1.975, -0.475)
    assert tuple(r.path_world[-1]) == (-0.475, 0.525)
    # The same run with cells gives the same path.
    same = pride.plan(g, tuple(r.path[0]), tuple(r.path[-1]), algo="astar")
    assert np.array_equal(same.path, r.path)
    # Without a frame: no path_world.
    plain = pride.plan(pride.Grid(np.zeros((3, 4))), (0, 0), (3, 2), algo="astar")
    assert plain.path_world is None


def test_unknown_cells_blocked_or_free(tmp_path):
    (tmp_path / "u.pgm").write_bytes(b"P5\n3 1\n255\n\xfe\xcd\xfe")
    (tmp_path / "u.yaml").write_text("image: u.pgm\nresolution: 1\norigin: [0, 0, 0]\n")
    assert pride.Grid.load(str(tmp_path / "u.yaml")).to_array().tolist() == [[0, 1, 0]]
    assert pride.Grid.load(str(tmp_path / "u.yaml"), unknown_free=True).to_array().tolist() == [[0, 0, 0]]
    with pytest.raises(TypeError, match="^unknown_free: "):
        pride.Grid.load(str(tmp_path / "u.yaml"), unknown_free="yes")
    # A campaign's problem reads its map file the same way.
    problem = {"id": "u", "grid": str(tmp_path / "u.yaml"), "start": (0, 0), "goal": (2, 0)}
    with pytest.raises(ValueError, match="cannot be reached"):
        pride.Campaign("u", seeds=1, problems=[problem], algorithms=["astar"]).run(tmp_path / "b.sqlite")
    # A* alone takes no budget: one it would not use is refused, as pride bench refuses it.
    with pytest.raises(ValueError, match="^iters: astar plans on the whole map in one search"):
        pride.Campaign("u", seeds=1, iters=1, problems=[{**problem, "unknown_free": True}], algorithms=["astar"])
    pride.Campaign("u", seeds=1, problems=[{**problem, "unknown_free": True}],
                   algorithms=["astar"]).run(tmp_path / "f.sqlite")
    assert pride.read_store(tmp_path / "f.sqlite", dataframe=False)[0]["best"] == 3.0  # cells, the default objective
    with pytest.raises(ValueError, match="unknown_free"):
        pride.Campaign("u", seeds=1, iters=1, problems=[{**problem, "grid": pride.Grid.load(str(tmp_path / "u.yaml")),
                                                "unknown_free": True}], algorithms=["astar"])


def test_errors_name_the_keyword(tmp_path, sandbox):
    g = pride.Grid.load(sandbox)
    with pytest.raises(ValueError, match=r"^start_world: the point \(30, 0\) is outside the map: x in \[-10, 9.2\)"):
        pride.plan(g, start_world=(30.0, 0.0), goal_world=(0, 0), algo="astar")
    # (0, 0) m is a blocked cell of the sandbox, (-2, -0.5) m a free one (where the robot starts).
    with pytest.raises(ValueError, match=r"^start_world: the point \(0, 0\) is in cell \(200,183\), a blocked cell"):
        pride.plan(g, start_world=(0, 0), goal_world=(-0.5, 0.5), algo="astar")
    with pytest.raises(TypeError, match="^goal_world: expected a number, got str"):
        pride.plan(g, start_world=(-2, -0.5), goal_world=("a", 0), algo="astar")
    with pytest.raises(TypeError, match=r"^start_world: expected \(x, y\) in metres, got str"):
        pride.plan(g, start_world="0,0", goal_world=(0, 0), algo="astar")
    with pytest.raises(ValueError, match="^start_world: the point must be finite"):
        pride.plan(g, start_world=(float("nan"), 0), goal_world=(0, 0), algo="astar")
    with pytest.raises(TypeError, match="^start_world: give start or start_world, not both"):
        pride.plan(g, (1, 1), start_world=(0, 0), goal_world=(0, 0), algo="astar")
    with pytest.raises(TypeError, match=r"^goal: give goal=\(x, y\) \(a cell\) or goal_world"):
        pride.plan(g, start_world=(-2, -0.5), algo="astar")
    with pytest.raises(ValueError, match="^start_world: the map array has no world frame"):
        pride.plan(pride.Grid(np.zeros((3, 4))), start_world=(0, 0), goal=(1, 1), algo="astar")
    (tmp_path / "y.yaml").write_text("image: m.pgm\nresolution: 0.05\norigin: [0, 0, 0.3]\n")
    with pytest.raises(ValueError) as e:
        pride.Grid.load(str(tmp_path / "y.yaml"))
    assert str(e.value) == str(tmp_path / "y.yaml") + ":3:16: origin yaw 0.3 is not supported: rotate the image"
    assert "\n" not in str(e.value)


def world_map(tmp_path):
    """A 240 x 4 map_server map, origin (-10, -10) m, 0.05 m per cell: a wall at column 100 over
    rows 0..2 and a full wall at column 235 (columns 236..239 cannot be reached from the left)."""
    pixels = bytearray()
    for y in range(4):
        for x in range(240):
            pixels.append(0 if (x == 100 and y <= 2) or x == 235 else 254)
    (tmp_path / "w.pgm").write_bytes(b"P5\n240 4\n255\n" + bytes(pixels))
    (tmp_path / "w.yaml").write_text("image: w.pgm\nresolution: 0.05\norigin: [-10, -10, 0]\n")
    return pride.Grid.load(str(tmp_path / "w.yaml"))


def test_a_point_on_a_border_lies_in_the_cell_after_it(tmp_path):
    g = world_map(tmp_path)
    # (1.6 + 10) / 0.05 is 232 in real numbers, 231.99999999999997 in floating point: the border
    # between columns 231 and 232 belongs to 232 (docs/grid.md). y = -9.9: row 2 from the bottom.
    r = pride.plan(g, start_world=(1.6, -9.9), goal_world=(-9.95, -10), algo="astar", objective="length")
    assert tuple(r.path[0]) == (232, 1)
    assert tuple(r.path[-1]) == (1, 3)
    same = pride.plan(g, (232, 1), (1, 3), algo="astar", objective="length")
    assert np.array_equal(same.path, r.path)


def test_lengths_in_metres_beside_cells(tmp_path):
    g = world_map(tmp_path)
    m = pride.plan(g, (232, 1), (1, 3), algo="astar", objective="length").path_metrics
    assert m["length_m"] == m["length"] * 0.05
    assert m["min_clearance_m"] == m["min_clearance"] * 0.05
    assert m["mean_clearance_m"] == m["mean_clearance"] * 0.05
    plain = pride.plan(pride.Grid(np.zeros((3, 4))), (0, 0), (3, 2), algo="astar").path_metrics
    assert not [k for k in plain if k.endswith("_m")]


def test_errors_about_world_points_name_the_world_keyword(tmp_path):
    g = world_map(tmp_path)
    with pytest.raises(ValueError, match=r"^start_world: the point \(-4.99, -9.85\) is in cell \(100,0\), a blocked "
                                         r"cell of "):
        pride.plan(g, start_world=(-4.99, -9.85), goal_world=(-9.95, -10), algo="astar")
    with pytest.raises(ValueError, match=r"^goal_world: \(238,3\) cannot be reached from the start \(232,1\)"):
        pride.plan(g, start_world=(1.6, -9.9), goal_world=(1.9, -10), algo="astar")
    with pytest.raises(ValueError, match=r"^start_world: the point \(1.6, -9.8\) is outside the map"):
        pride.plan(g, start_world=(1.6, -9.8), goal_world=(1.6, -9.9), algo="astar")
    # The cell keywords keep their names.
    with pytest.raises(ValueError, match=r"^goal: \(238,3\) cannot be reached"):
        pride.plan(g, start_world=(1.6, -9.9), goal=(238, 3), algo="astar")
    with pytest.raises(ValueError, match=r"^start: \(100,0\) is a blocked cell"):
        pride.plan(g, (100, 0), goal_world=(1.6, -9.9), algo="astar")
