"""Helpers shared by the tests and the benchmarks (never a test module; nothing here is collected).

- :mod:`.geometry_cases`: analytic shapes with their exact axis (numpy and shapely only);
- :mod:`.oracle`: the independent segment-Voronoi medial-axis oracle and exact distances;
- :mod:`.project`: paths and metadata of the repository, for the plugin tests.

Import as ``tests.support`` with the repository root on ``sys.path`` (pytest.ini's ``pythonpath``; the
benchmarks put the root there themselves).
"""
