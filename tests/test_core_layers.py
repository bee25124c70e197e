"""Layers of touching polygons: gates (``core.touching``), layer networks (``core.layers``) and ``frames.networks``.

The generated layer (``tests/support/river_layer.py``) is rivers with tributaries cut across the main stem
at random gates: every reach's lines must meet its neighbours' exactly (end-to-end distance 0, one shared
node id per gate) and each river must be one connected network.
"""

import numpy as np
import pytest
import shapely
from shapely.geometry import Polygon, box

from incircu_plugin.core import polygon_network
from incircu_plugin.core.errors import IncirCuError
from incircu_plugin.core.layers import layer_networks
from incircu_plugin.core.touching import touching_gates
from tests.support import network_cases as cases
from tests.support.river_layer import river_reaches
from tests.test_core_network import check_network


def components(layer):
    """Connected components of the layer's node graph: node id -> component root."""
    parent = list(range(len(layer.nodes)))

    def root(node):
        while parent[node] != node:
            parent[node] = parent[parent[node]]
            node = parent[node]
        return node

    for branch in layer.branches:
        parent[root(branch["from_node"])] = root(branch["to_node"])
    return [root(node) for node in range(len(layer.nodes))]


def check_layer(reaches, river_of, layer):
    """Every gate joins exactly the lines of two reaches at one node; every river is one network."""
    assert not layer.errors, layer.errors[:3]
    assert {branch["feature"] for branch in layer.branches} == set(range(len(reaches)))
    _, gates = touching_gates(reaches)
    ends_at = {}
    for branch in layer.branches:
        coordinates = shapely.get_coordinates(branch["geometry"])
        for node, xy in ((branch["from_node"], coordinates[0]), (branch["to_node"], coordinates[-1])):
            # Each line ends exactly at its node.
            assert tuple(xy) == layer.nodes[node]["geometry"].coords[0]
            ends_at.setdefault(node, set()).add(branch["feature"])
    for feature, points in enumerate(gates):
        for gate in points:
            (node,) = [n for n, data in enumerate(layer.nodes) if data["geometry"].coords[0] == tuple(gate)]
            assert len(ends_at[node]) == 2 and feature in ends_at[node], "a gate joins exactly two reaches"
    roots = components(layer)
    for river in set(river_of):
        features = [i for i, r in enumerate(river_of) if r == river]
        nodes = {b[end] for b in layer.branches if b["feature"] in features for end in ("from_node", "to_node")}
        assert len({roots[node] for node in nodes}) == 1, f"river {river} is not one network"


def test_touching_gates_are_the_middles_of_shared_stretches_and_vertices_of_both():
    shapes, gates = touching_gates([box(0, 0, 50, 10), box(50, 0, 100, 10), box(100, -20, 110, 30), None])
    assert [g.tolist() for g in gates] == [[[50.0, 5.0]], [[50.0, 5.0], [100.0, 5.0]], [[100.0, 5.0]], []]
    for shape, points in zip(shapes[:3], gates[:3]):
        ring = shapely.get_coordinates(shape.exterior)
        assert all(np.any(np.all(ring == gate, axis=1)) for gate in points)
        assert shape.equals(shape.normalize())  # the same region, one vertex more
    # Corners touching at a point make no gate.
    _, gates = touching_gates([box(0, 0, 10, 10), box(10, 10, 20, 20)])
    assert [len(g) for g in gates] == [0, 0]


def test_a_gate_in_the_middle_of_a_bank_is_joined_by_an_exact_junction():
    polygon, _, _, _ = cases.t_junction()
    network = polygon_network(polygon, [(20.0, -5.0)])
    assert len(network.split_points) == 4
    check_network(polygon, network)
    # The junction's circle touches the gate and the far bank: centre 5 above the gate, radius 5.
    assert np.min(np.hypot(*(network.junctions - (20.0, 0.0)).T)) <= 1e-9 * 100.0


def test_ends_from_names_the_gates_when_a_reach_has_no_split_point():
    # A river cut into three reaches: the middle one ends at its two gates only, the outer ones at a gate and
    # an automatic end; a given split point with a gate names both.
    reaches = [box(0, 0, 50, 10), box(50, 0, 100, 10), box(100, 0, 150, 10)]
    shapes, gates = touching_gates(reaches)
    found = [polygon_network(shape, gates=points) for shape, points in zip(shapes, gates)]
    assert [network.ends_from for network in found] == ["gates_and_automatic", "gates", "gates_and_automatic"]
    assert found[1].end_sources == ("gate", "gate")
    assert [sorted(network.end_sources) for network in found[::2]] == [["automatic", "gate"]] * 2
    given = polygon_network(shapes[0], [(0.0, 5.0)], gates=gates[0])
    assert given.ends_from == "split_points_and_gates" and given.end_sources == ("split_point", "gate")
    assert polygon_network(shapes[0], [(0.0, 5.0), (50.0, 5.0)]).ends_from == "split_points"


def test_a_feature_whose_gates_fail_is_warned_about_and_the_others_keep_theirs(monkeypatch):
    # A NaN coordinate made GEOS raise in the spatial query (it aborted the whole layer): that feature now shares
    # nothing and fails alone; its neighbours still meet each other.
    with np.errstate(invalid="ignore"):
        nan = Polygon([(100, 0), (np.nan, 0), (150, 10), (100, 10)])
    layer = layer_networks([box(0, 0, 50, 10), box(50, 0, 100, 10), nan], connect_touching=True)
    assert [error[0] for error in layer.errors] == [2] and not layer.warnings
    assert {branch["feature"] for branch in layer.branches} == {0, 1}
    assert sum(node["degree"] == 2 for node in layer.nodes) == 1  # the one gate joins reaches 0 and 1


def test_geos_failing_on_one_pair_warns_about_its_features_and_keeps_the_other_gates(monkeypatch):
    # GEOS raising on the shared boundary of reaches 0 and 1 (both valid): both are warned about and computed
    # without that gate; reaches 1 and 2 keep theirs. Without a list for the errors, touching_gates raises.
    from incircu_plugin.core import touching

    def failing(a, b, **kwargs):
        if all(a is not None and (50.0, 0.0) in map(tuple, shapely.get_coordinates(g)) for g in (a, b)):
            raise shapely.errors.GEOSException("TopologyException: side location conflict")
        return shapely.intersection(a, b, **kwargs)

    geos = type(
        "Geos", (), {"__getattr__": lambda self, name: getattr(shapely, name), "intersection": staticmethod(failing)}
    )
    monkeypatch.setattr(touching, "shapely", geos())
    reaches = [box(0, 0, 50, 10), box(50, 0, 100, 10), box(100, 0, 150, 10)]
    layer = layer_networks(reaches, connect_touching=True)
    assert [warning[0] for warning in layer.warnings] == [0, 1] and not layer.errors
    assert all("side location conflict" in warning[2] for warning in layer.warnings)
    ends = {branch["feature"]: {branch["from_point"], branch["to_point"]} for branch in layer.branches}
    assert ends == {0: {"auto"}, 1: {"auto", "gate"}, 2: {"auto", "gate"}}
    with pytest.raises(IncirCuError, match="could not be computed"):
        touching_gates(reaches)


def test_a_confluence_reach_touching_three_neighbours_is_a_network_between_its_three_gates():
    # The T of roads 10 and 6 wide cut into its junction reach and three arms: the junction reach's ends are its
    # three gates only (no automatic end), its three branches meet at the T's exact junction, and each gate
    # joins it to one arm.
    polygon, _, (junction,), radius = cases.t_junction()
    cut = 20.0
    windows = [box(-cut, -10, cut, cut), box(-60, -10, -cut, 60), box(cut, -10, 60, 60), box(-cut, cut, cut, 60)]
    reaches = [polygon.intersection(window) for window in windows]
    shapes, gates = touching_gates(reaches)
    assert len(gates[0]) == 3
    network = polygon_network(shapes[0], gates=gates[0])
    assert network.ends_from == "gates" and len(network.branches) == 3
    check_network(shapes[0], network)
    tolerance = 1e-9 * 2.0 * cut  # the reach's extent
    assert np.hypot(*(network.junctions[0] - junction)) <= tolerance
    assert abs(network.junction_radii[0] - radius) <= tolerance
    layer = layer_networks(reaches, connect_touching=True)
    check_layer(reaches, [0] * len(reaches), layer)
    middle = [branch for branch in layer.branches if branch["feature"] == 0]
    assert sorted(branch["from_point"] for branch in middle) == ["gate"] * 3
    assert sorted(node["degree"] for node in layer.nodes) == [1, 1, 1, 2, 2, 2, 3]


def test_reaches_of_generated_rivers_meet_their_neighbours_exactly():
    reaches, river_of = river_reaches(rivers=2, cuts_per_river=6, seed=7)
    layer = layer_networks(reaches, connect_touching=True)
    check_layer(reaches, river_of, layer)


@pytest.mark.slow
def test_two_thousand_reaches_of_generated_rivers_meet_their_neighbours_exactly():
    reaches, river_of = river_reaches(rivers=185, cuts_per_river=10)
    assert len(reaches) >= 2000
    layer = layer_networks(reaches, connect_touching=True)
    check_layer(reaches, river_of, layer)


def test_geographic_reaches_meet_exactly_in_degrees():
    # Two reaches of a river 10 m wide at 52 N, in degrees: each computed in metres around itself.
    east, north = 1.0 / 68_000.0, 1.0 / 111_000.0
    reaches = [
        box(19.0, 52.0, 19.0 + 50 * east, 52.0 + 10 * north),
        box(19.0 + 50 * east, 52.0, 19.0 + 100 * east, 52.0 + 10 * north),
    ]
    layer = layer_networks(reaches, connect_touching=True, geographic_crs="EPSG:4326")
    assert not layer.errors
    first, second = (shapely.get_coordinates(branch["geometry"]) for branch in layer.branches)
    shared = {layer.branches[0]["from_node"], layer.branches[0]["to_node"]} & {
        layer.branches[1]["from_node"],
        layer.branches[1]["to_node"],
    }
    assert len(shared) == 1
    ends = {tuple(first[0]), tuple(first[-1])} & {tuple(second[0]), tuple(second[-1])}
    assert len(ends) == 1
    assert 49.0 < sum(branch["length"] for branch in layer.branches) / 2.0 < 51.0  # metres


def test_frames_networks_number_nodes_across_features():
    geopandas = pytest.importorskip("geopandas")
    from incircu_plugin.core.frames import networks

    reaches = geopandas.GeoDataFrame(
        {"name": ["a", "b", "bad"]},
        geometry=[box(0, 0, 50, 10), box(50, 0, 100, 10), shapely.Polygon([(500, 0), (504, 4), (504, 0), (500, 4)])],
        crs="EPSG:2180",
        index=[10, 20, 30],
    )
    branches, nodes = networks(reaches, connect_touching=True, nodes=True)
    good = branches[branches["error"].isna()]
    assert good["source"].tolist() == [10, 20]
    assert good["from_point"].tolist() == ["gate", "gate"] and good["kind"].tolist() == ["arm", "arm"]
    (shared,) = set(good["from_node"])  # both lines start at the gate
    assert nodes.loc[shared, "degree"] == 2 and nodes.loc[shared].geometry.coords[0] == (50.0, 5.0)
    (failed,) = branches[branches["error"].notna()].itertuples()
    assert failed.source == 30 and failed.geometry is None and "Self-intersection" in failed.error
    assert branches.crs == reaches.crs and nodes.crs == reaches.crs
