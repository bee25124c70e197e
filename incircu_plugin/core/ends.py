"""Automatic ends: the two boundary points a person would call the ends of an elongated polygon.

The ends are the extremities of a path along the polygon's skeleton (an approximation of its medial axis,
see :mod:`.skeleton`), not the farthest pair of points in a straight line: a U-shaped or meandering river
gets its two tips, a Y-shaped one the tips of two of its arms.

Rule, step by step (deterministic, about O(n log n) in the number ``n`` of boundary samples):

1. **Skeleton.** See :mod:`.skeleton`. The polygon is first moved to the origin and scaled to a unit
   bounding-box diagonal, so any coordinate size (1e-170 to 1e155) gives the same answer. Its islands
   smaller than the typical width are left out (see :func:`_without_small_islands`): they never decide which
   tips are the ends, but one beside a bank could pull the path through the gap to a corner of the cap.
2. **Path.** The path between two skeleton leaves that is heaviest under the chosen rule, by a double sweep
   (see :mod:`.paths`; exact without holes, a close approximation around islands):

   - ``"main_stem"`` (default): each skeleton edge weighs its length times the width there, so the path
     maximises the channel *area it sweeps*. A wide main river beats a longer but narrower side arm; an arm
     wins only when its length times its width exceeds what the main river keeps beyond the junction.
     Limits: a reservoir whose longest arm is also wide (a drowned tributary as wide as the main valley)
     gets that arm; a delta's distributaries are compared by area only.
   - ``"longest_path"``: each edge weighs its length: the tips of the two longest arms.
   - with a *guide* line (``guide=``): each skeleton node earns the guide length lying nearest to it (after
     resampling the guide every eighth of the typical width and dropping what lies farther than
     ``GUIDE_REACH`` typical widths from the polygon) times its width, and each edge half the earnings of its two nodes, plus ``GUIDE_TIE``
     times its main-stem weight: the path covers as much of the guide as a skeleton path can, and beyond
     the guide it follows the main stem. Gaps, offsets, pieces outside the polygon and generalisation of
     the guide only remove a little of the earnings; a tributary in the guide is followed only if its
     covered length times its width exceeds the main river's.
3. **Cap centring.** Near each end the path runs into a corner or a rounded cap, not to the middle of the
   end. Walking inward from the tip, ``d`` is the distance travelled (plus the tip's own clearance) and
   ``r`` the radius of the largest inscribed disk there. The *last trunk point* ``T`` is the widest
   skeleton junction (a triangle with no side on the boundary: where the branches from the two corners of a
   flat cap, or the fan of a rounded cap, meet the trunk) with ``d <= CAP_WINDOW * r``. Without such a
   junction (a pointed end), ``T`` is where ``d`` first exceeds ``CAP_REACH * r``: up to there the disk
   still reaches back to the tip, so the path is in the end cap. Its disk touches the two banks at ``L``
   and ``R`` (the boundary points nearest to ``T +- r * n``, ``n`` normal to the trunk),
   and the trunk's continuation (the ray from ``T`` perpendicular to ``L - R``, the medial-axis tangent)
   leaves the exterior ring at ``X``. The *end cap* is the arc of the exterior ring from ``R`` to ``L``
   through ``X`` (``X`` itself is the end if that arc were over half the ring). Its *corners* are the
   vertices where the boundary turns by ``CORNER_TURN`` or more towards the inside. The end is the
   arc-length midpoint between the first and last corner (a flat or oblique cut: the middle of the cut,
   the midpoint of a rectangle's short side), the corner itself when there is one (a pointed end), or the
   arc-length midpoint of the whole cap when there is none (a rounded cap: its apex).
4. **Distinct ends.** Should both ends fall within ``MIN_SEPARATION`` of the extent of each other (a compact
   shape), the second end becomes the point of the exterior ring half its perimeter away from the first.
5. **Shapes without a dominant trunk** (not with a guide; :attr:`EndsResult.kind`, and the caller's note).
   The *centre* is the centroid of the exterior ring's polygon; its *clearance* its distance from the ring.

   - *Star-like*: the parts of the outline beyond ``STAR_DISK`` clearances of the centre that reach
     ``STAR_ARM`` clearances are its arms; with three or more, none reaching beyond ``STAR_REACH``
     clearances, and the third-longest reaching ``STAR_EVEN`` of the second-longest, the ends are the tips
     (farthest vertices) of the two arms whose tips lie farthest apart: a path through the centre (two
     opposite arms of an even star, two arms 144 degrees apart of a five-armed one), whatever holes it has.
   - *Compact* (not elongated, see :attr:`EndsResult.elongated`, and not star-like): the ends are where the
     longest axis through the centre (the centre of the largest inscribed disk when the centroid lies outside
     or within half that disk's radius of the ring) leaves the exterior ring: the principal axis of the larger
     second moment of area, or, on a shape with none (moments equal up to ``ISOTROPY``: a square, a regular
     polygon), the line from the centre to the nearest point of the ring. A rectangle's short sides'
     middles, an ellipse's tips at any vertex count, a square's opposite sides' middles, a regular polygon's
     side middle and the vertex or side middle opposite.

   An elongated shape with a dominant trunk keeps the ends of steps 1 to 4.

Limits: an oblique cut sharper than ``CORNER_TURN`` at its obtuse corner ends at its acute corner; the
skeleton is only as fine as the sampling, so features narrower than a quarter of the typical width may be
missed (they do not change the ends of an elongated shape); an island wider than the typical width close to
an end can still pull that end to a corner of the cap (the ends of the outline alone are those found with the
islands ignored).

The *start* is the end with the smaller ``x`` coordinate (the smaller ``y`` when their ``x`` differ by at most
``SAME_X`` of the extent, as the two ends of a north-south box do up to rounding), so the answer does not depend
on where the ring starts or which way it turns.

**Batches.** :func:`find_ends_together` finds the ends of many polygons with the same answers as
:func:`find_ends` on each (which runs the same code on a batch of one): the triangulations (one GEOS call per
refinement round for all), the skeletons, the chain contraction, the double sweeps (see :mod:`.paths`) and
the cap centring work on flat arrays of all polygons, each polygon numbered and summed on its own; only the
results are Python per polygon (costs: docs/core-notes.md).
"""

from dataclasses import dataclass
from typing import Optional

import numpy as np
import shapely
from shapely.geometry import LineString, Point
from shapely.ops import polylabel

from ._arrays import ranges
from .chains import extent_of, validate_polygon
from .errors import Cancelled, IncirCuError, InvalidGeometryError, Message
from .paths import heaviest_paths
from .polyline import counterclockwise, turns_between, typical_width
from .skeleton import joint_skeletons

#: Rules for the automatic ends (see the module docstring).
END_RULES = ("main_stem", "longest_path")

#: ``d / r`` below which a skeleton point still belongs to the end cap: ``1 / sin(40 deg)``, so corners of
#: 80 degrees or blunter (a flat cap meets its banks at about 90 degrees) and rounded caps are centred.
CAP_REACH = 1.0 / np.sin(np.radians(40.0))

#: Left turn of a counter-clockwise exterior ring at which a vertex of an end cap counts as a corner
#: (an interior angle of 140 degrees or sharper), radians.
CORNER_TURN = np.radians(40.0)

#: Reach, in radii of the inscribed disk, of the window next to a tip in which the skeleton junction where
#: the corner branches of an end cap meet is looked for (a right-angled corner's branch meets at 1.41).
CAP_WINDOW = 3.0

#: Ratio of the longest skeleton path to the largest inscribed diameter under which a shape is not
#: elongated (a circle scores 1, a square about 1.4, a 2:1 rectangle about 2.4).
ELONGATION_THRESHOLD = 2.0

#: Weight of the main-stem rule next to the guide's earnings, which it only breaks ties between.
GUIDE_TIE = 1e-2

#: Distance from the polygon, in typical widths, beyond which guide samples are ignored.
GUIDE_REACH = 2.0

#: Two ends closer than this fraction of the bounding-box diagonal are the same end (see rule 4).
MIN_SEPARATION = 1e-5

#: Largest distance of an end from the exterior ring, as a fraction of the bounding-box diagonal (a tenth of
#: the default snap tolerance of the split points).
ON_RING = 1e-7

#: Two ends whose x differ by at most this fraction of the bounding-box diagonal have the same x for the
#: start rule (the rounding of the cap centring is about 1e-15 of it).
SAME_X = 1e-9

#: Star-like shapes (see the module docstring, step 5): the disk around the centre that cuts the arms apart,
#: in clearances of the centre (the notches between a regular star's arms lie at one clearance).
STAR_DISK = 1.5

#: Smallest reach of an arm from the centre, in clearances of the centre, for it to count as an arm of a
#: star (a triangle's corners reach 2, a regular star's tips 2.5 when its notches lie at 0.4 of its tips).
STAR_ARM = 2.25

#: Smallest reach of a star's third-longest arm, as a fraction of its second-longest's: with a shorter third
#: arm the two longest are a dominant trunk (a reservoir's main valley beside a short side arm), whose tips
#: the skeleton path finds.
STAR_EVEN = 0.5

#: Largest reach of any part of the outline from the centre, in clearances of the centre, of a star-like
#: shape (a river's arms reach further: its centre has no dominant place, its trunk decides).
STAR_REACH = 12.0

#: Relative difference of the outline's two principal second moments below which a compact shape has no
#: longest axis (a square, a regular polygon: only rounding separates them).
ISOTROPY = 1e-9

#: Kinds of shape (:attr:`EndsResult.kind`).
ELONGATED, COMPACT, STAR = "elongated", "compact", "star"

#: Largest and smallest bounding-box diagonal, CRS units, that the computation handles.
LARGEST_EXTENT = 1e300
SMALLEST_EXTENT = 1e-300


#: Guide lines are looked for within this share of a polygon's larger bounding-box side around the box (the
#: plugin's and the data-frame API's candidate search; the core then keeps the guide lying near the polygon).
GUIDE_SEARCH_SHARE = 0.25


@dataclass(frozen=True)
class EndsResult:
    """The two ends found on a polygon's boundary.

    Attributes
    ----------
    start : Point
        First end, on the exterior ring (the one with the smaller x, or y when both have the same x up to
        ``SAME_X`` of the extent), CRS units.
    end : Point
        Second end, on the exterior ring, CRS units.
    elongated : bool
        False when the shape is not elongated (its longest skeleton path is shorter than
        ``ELONGATION_THRESHOLD`` times its largest inscribed diameter); the ends then lie across its centre
        (``kind`` ``"compact"``, or ``"star"``; only a guide leaves them where its path ends), and the caller
        should warn.
    trunk : LineString or None
        The skeleton path the ends were derived from (diagnostics), CRS units; it may cross islands smaller
        than the typical width, which the skeleton leaves out; None where that path is one point (a ring's
        skeleton is a cycle without leaves). A compact or star-like shape's ends are not this path's.
    guided : bool
        True when a guide line came near the polygon and chose the path.
    kind : {"elongated", "compact", "star"}
        How the ends were chosen (see the module docstring, step 5): ``"elongated"``, the tips of the
        skeleton path; ``"compact"`` (a shape that is not elongated), the two points where its longest axis
        through its centre leaves it; ``"star"`` (three or more arms around a centre, no dominant trunk), the
        tips of its two farthest-apart arms. The last two have no dominant trunk: the caller should say so.
        Always ``"elongated"`` with a guide.
    """

    start: Point
    end: Point
    elongated: bool
    trunk: Optional[LineString] = None
    guided: bool = False
    kind: str = ELONGATED


def find_ends(polygon, *, rule="main_stem", guide=None, progress=None):
    """Find the two boundary points a person would call the ends of a polygon.

    See the module docstring for the rules (a heaviest skeleton path, then cap centring).

    Parameters
    ----------
    polygon : Polygon
        A valid polygon, possibly with holes (islands), CRS units.
    rule : {"main_stem", "longest_path"}
        Path rule without a guide, or beyond it.
    guide : LineString or MultiLineString, optional
        A rough line of the river (same CRS); where it comes near the polygon the path follows it.
    progress : callable, optional
        Called with the fraction done (0 to 1); returning False stops the search with :class:`Cancelled`.

    Returns
    -------
    EndsResult
        ``start`` and ``end`` on the boundary of the polygon, and whether the shape is elongated.

    Raises
    ------
    InvalidGeometryError
        If the polygon (or the guide) is null, empty, of the wrong kind, not finite, not valid or
        absurdly scaled, or so degenerate that no skeleton can be built.
    IncirCuError
        If ``rule`` is unknown.
    Cancelled
        If ``progress`` returned False.

    Examples
    --------
    >>> from shapely.geometry import box
    >>> ends = find_ends(box(0, 0, 10, 2))
    >>> [round(c, 6) for c in ends.start.coords[0] + ends.end.coords[0]]
    [0.0, 1.0, 10.0, 1.0]
    """
    (outcome,) = _ends_together([polygon], _checked_rule(rule), [guide], _cancel_check(progress))
    if isinstance(outcome, Exception):
        raise outcome
    return outcome


def find_ends_together(polygons, *, rule="main_stem", guides=None, progress=None):
    """Find the ends of many polygons at once: :func:`find_ends` of each, with the same answers.

    The polygons are triangulated one by one (one GEOS call each); their skeletons, the contraction of the
    skeletons' chains and the weights are then computed together, so a batch of small features pays the
    numpy calls' overhead once instead of once per feature.

    Parameters
    ----------
    polygons : sequence of Polygon
        CRS units (each in its own; they need not be apart).
    rule : {"main_stem", "longest_path"}
        Path rule, as for :func:`find_ends`.
    guides : sequence of (LineString or MultiLineString or None), optional
        One guide per polygon (see :func:`find_ends`); None: no guides.
    progress : callable, optional
        Called with the fraction done (0 to 1); returning False stops the search with :class:`Cancelled`.

    Returns
    -------
    list
        Per polygon, in order: its :class:`EndsResult`, or the exception :func:`find_ends` raises for it
        (an ``Exception`` instance, such as :class:`InvalidGeometryError` for an invalid or too thin one).

    Raises
    ------
    IncirCuError
        If ``rule`` is unknown, or ``guides`` has not one entry per polygon.
    Cancelled
        If ``progress`` returned False.

    Examples
    --------
    A self-crossing polygon gets its error; the others their ends:

    >>> from shapely.geometry import Polygon, box
    >>> bow_tie = Polygon([(0, 0), (4, 4), (4, 0), (0, 4)])
    >>> good, bad = find_ends_together([box(5, 5, 35, 9), bow_tie])
    >>> [round(c, 6) for c in good.end.coords[0]], type(bad).__name__
    ([35.0, 7.0], 'InvalidGeometryError')
    """
    polygons = list(polygons)
    guides = [None] * len(polygons) if guides is None else list(guides)
    if len(guides) != len(polygons):
        raise IncirCuError(Message("guides_count", guides=len(guides), polygons=len(polygons)))
    return _ends_together(polygons, _checked_rule(rule), guides, _cancel_check(progress))


def _checked_rule(rule):
    """Return ``rule``; raise :class:`IncirCuError` if it is not one of ``END_RULES``."""
    if rule not in END_RULES:
        raise IncirCuError(Message("unknown_end_rule", rule=rule, choices=", ".join(END_RULES)))
    return rule


def _validate_guide(guide):
    """Raise :class:`InvalidGeometryError` unless ``guide`` is None or a finite (multi)line."""
    if guide is None:
        return
    if getattr(guide, "geom_type", None) not in ("LineString", "MultiLineString"):
        kind = getattr(guide, "geom_type", type(guide).__name__)
        raise InvalidGeometryError(Message("guide_kind", kind=kind))
    if not np.all(np.isfinite(shapely.get_coordinates(guide))):
        raise InvalidGeometryError(Message("guide_not_finite"))


def _cancel_check(progress):
    """Return ``check(fraction)`` that raises :class:`Cancelled` when ``progress(fraction)`` is False."""

    def check(fraction):
        if progress is not None and progress(fraction) is False:
            raise Cancelled()

    return check


@dataclass
class _LocalPolygon:
    """A polygon moved to its local frame (origin at its box centre, unit bounding-box diagonal).

    Attributes
    ----------
    polygon : Polygon
        The input, CRS units.
    origin : ndarray of shape (2,)
        Centre of its bounding box, CRS units.
    scale : float
        Its bounding-box diagonal, CRS units.
    local : Polygon
        The polygon in the local frame, counter-clockwise.
    guide : LineString or MultiLineString or None
        The guide in the local frame.
    """

    polygon: object
    origin: np.ndarray
    scale: float
    local: object
    guide: object


def _local_box(polygon, guide):
    """Return the origin and scale of a polygon's local frame (see :class:`_LocalPolygon`) after validating it and its
    guide; raise as :func:`find_ends`."""
    validate_polygon(polygon)
    _validate_guide(guide)
    bounds = np.asarray(polygon.bounds, dtype=float)
    origin = (bounds[:2] + bounds[2:]) / 2.0
    scale = extent_of(bounds.reshape(2, 2))
    if not SMALLEST_EXTENT <= scale <= LARGEST_EXTENT:
        raise InvalidGeometryError(Message("polygon_size_absurd", size=scale))
    return origin, scale


def _without_small_islands(polygon):
    """Return the polygon without its holes smaller than its outline's typical width (their bounding boxes'
    diagonals, CRS units).

    Such an island never decides which tips are the ends, but around it the skeleton has a cycle, and the
    sweeps' shortest way around a cycle takes its narrower side: a small island beside a bank near an end
    would pull the path through that gap and the end to a corner of the cap, and a field of them would turn
    the skeleton into a maze.
    """
    if not polygon.interiors:
        return polygon
    outline = shapely.Polygon(polygon.exterior)
    width = typical_width(outline.area, outline.length / 2.0)
    holes = np.array(polygon.interiors, dtype=object)
    west, south, east, north = shapely.bounds(holes).T
    kept = holes[np.hypot(east - west, north - south) >= width]
    return shapely.Polygon(polygon.exterior, kept.tolist())


def _moved(geometries, origin, scale):
    """Return the geometries with each coordinate ``xy`` moved to ``(xy - origin) / scale`` (the origin and
    scale of its frame, or one row of them per coordinate)."""
    return shapely.transform(geometries, lambda xy: (xy - origin) / scale)


def _frames(polygons, guides, boxes, every_island=False):
    """Return the :class:`_LocalPolygon` of each polygon with a local box (None for the others); the polygons are moved
    all at once, the guides one by one.

    Parameters
    ----------
    polygons, guides : list
    boxes : list of tuple or None
        Per polygon, the ``(origin, scale)`` of :func:`_local_box`, or None.
    every_island : bool
        Keep the islands smaller than the typical width too (see :func:`_without_small_islands`).
    """
    frames = [None] * len(polygons)
    chosen = [index for index, box in enumerate(boxes) if box is not None]
    if not chosen:
        return frames
    origins = np.array([boxes[index][0] for index in chosen])
    scales = np.array([boxes[index][1] for index in chosen])
    geometries = np.empty(len(chosen), dtype=object)
    geometries[:] = [polygons[index] if every_island else _without_small_islands(polygons[index]) for index in chosen]
    owner = np.repeat(np.arange(len(chosen)), shapely.get_num_coordinates(geometries))
    # Without repeated vertices: GEOS 3.11 locates a point on a zero-length segment by dividing 0 by 0, and
    # numpy then warns "invalid value encountered in line_locate_point" (the answer is right).
    local = counterclockwise(shapely.remove_repeated_points(_moved(geometries, origins[owner], scales[owner, None])))
    for number, index in enumerate(chosen):
        origin, scale = boxes[index]
        guide = guides[index]
        local_guide = None if guide is None else _moved(guide, origin, scale)
        frames[index] = _LocalPolygon(polygons[index], origin, scale, local[number], local_guide)
    return frames


def _as_outcome(error):
    """Return the exception :func:`find_ends` raises for ``error`` (a GEOS error becomes invalid geometry)."""
    if isinstance(error, shapely.errors.GEOSException):
        wrapped = InvalidGeometryError(Message("ends_geos", error=str(error)))
        wrapped.__cause__ = error
        error = wrapped
    error.__traceback__ = None
    return error


def _each(items, compute, outcomes, check, begin, end):
    """Return ``compute(i, item)`` for each item whose outcome is not yet known, None where it raised then.

    An item that raises gets its error as outcome (see :func:`_as_outcome`).

    ``check`` gets fractions from ``begin`` to ``end`` now and then; :class:`Cancelled` passes through.
    """
    results = [None] * len(items)
    every = max(1, len(items) // 16)
    for index, item in enumerate(items):
        if outcomes[index] is not None:
            continue
        if index % every == 0:
            check(begin + (end - begin) * index / len(items))
        try:
            results[index] = compute(index, item)
        except Cancelled:
            raise
        except Exception as error:  # noqa: BLE001 - one polygon's failure is its outcome, not the batch's
            outcomes[index] = _as_outcome(error)
    return results


def _ends_together(polygons, rule, guides, check):
    """Return each polygon's :class:`EndsResult` or exception (see :func:`find_ends_together`)."""
    check(0.0)
    outcomes = [None] * len(polygons)
    boxes = _each(polygons, lambda index, polygon: _local_box(polygon, guides[index]), outcomes, check, 0.0, 0.5)
    check(0.5)
    try:
        frames = _frames(polygons, guides, boxes)
        trunks = _joint_trunks(frames, rule, outcomes, check)
        check(0.8)
        results = _ends_of_trunks(frames, trunks)
    except Cancelled:
        raise
    except Exception as error:  # noqa: BLE001 - find which polygon fails, and let the others through
        if len(polygons) == 1:
            return [_as_outcome(error)]
        return [_ends_together([polygon], rule, [guide], _no_check)[0] for polygon, guide in zip(polygons, guides)]
    check(1.0)
    return [result if outcome is None else outcome for result, outcome in zip(results, outcomes)]


def _no_check(fraction):
    """A progress check that never cancels."""


def _joint_trunks(frames, rule, outcomes, check, skeleton=None):
    """Return per frame its trunk ``(points, radii, junction, step, guided)``, None for a failed one.

    The skeletons of all frames are built (unless ``skeleton``, the :func:`.skeleton.joint_skeletons` of the
    frames' local polygons, is given), weighed and contracted together (see :func:`.paths.heaviest_paths`).
    A polygon that cannot be triangulated, or whose skeleton has no edge, gets :class:`InvalidGeometryError`
    in ``outcomes``.
    """
    trunks = [None] * len(frames)
    framed = [index for index, frame in enumerate(frames) if frame is not None]
    if not framed:
        return trunks
    if skeleton is None:
        skeleton = joint_skeletons([frames[index].local for index in framed])
    nodes, spans, edges = skeleton.nodes, skeleton.spans, skeleton.edges
    node_start = np.searchsorted(skeleton.owner, np.arange(len(framed) + 1))
    edge_owner = skeleton.owner[edges[:, 0]]
    edge_order = np.argsort(edge_owner, kind="stable")
    edge_start = np.searchsorted(edge_owner[edge_order], np.arange(len(framed) + 1))
    weights = _rule_weights(nodes, spans, edges, rule)
    starts, trees, chosen = [], [], []
    for position, index in enumerate(framed):
        if skeleton.errors[position] is not None or edge_start[position + 1] == edge_start[position]:
            outcomes[index] = skeleton.errors[position] or InvalidGeometryError(Message("ends_too_thin"))
            continue
        low, high = node_start[position], node_start[position + 1]
        own_edges = edge_order[edge_start[position] : edge_start[position + 1]]
        own_nodes = slice(low, high)
        guided = frames[index].guide is not None and _guide_weights(
            frames[index], skeleton, weights, own_nodes, own_edges
        )
        starts.append(low + int(np.argmax(skeleton.radii[low:high])))
        trees.append(len(frames[index].local.interiors) == 0)
        chosen.append((index, position, guided))
    paths = heaviest_paths(len(nodes), edges, weights, starts, trees, check=lambda: check(0.6))
    junction = np.bincount(edges.ravel(), minlength=len(nodes)) >= 3
    for (index, position, guided), path in zip(chosen, paths):
        step = float(skeleton.steps[position])
        trunks[index] = (nodes[path], skeleton.radii[path], junction[path], step, guided)
    return trunks


def _rule_weights(nodes, spans, edges, rule):
    """Return the weight of each skeleton edge under ``rule``: its swept area or its length, CRS units."""
    lengths = np.hypot(*(nodes[edges[:, 0]] - nodes[edges[:, 1]]).T)
    return lengths * 0.5 * (spans[edges[:, 0]] + spans[edges[:, 1]]) if rule == "main_stem" else lengths


def _guide_weights(frame, skeleton, weights, own_nodes, own_edges):
    """Set one polygon's edge weights from its guide when the guide counts; return whether it did.

    Each edge then weighs half the guide earnings of its two nodes (see :func:`_guide_earnings`) plus
    ``GUIDE_TIE`` times its swept area.

    Parameters
    ----------
    frame : _LocalPolygon
        The polygon and its guide, in its local frame.
    skeleton : Skeletons
        The batch's skeletons.
    weights : ndarray of shape (e,)
        The batch's edge weights, changed in place.
    own_nodes : slice
        The polygon's nodes in ``skeleton``.
    own_edges : ndarray of int
        The polygon's edges in ``skeleton``.
    """
    nodes, spans = skeleton.nodes[own_nodes], skeleton.spans[own_nodes]
    earnings = _guide_earnings(frame.local, nodes, spans, frame.guide)
    if earnings is None or not np.any(earnings > 0.0):
        return False
    edges = skeleton.edges[own_edges] - own_nodes.start
    area = _rule_weights(nodes, spans, edges, "main_stem")
    weights[own_edges] = 0.5 * (earnings[edges[:, 0]] + earnings[edges[:, 1]]) + GUIDE_TIE * area
    return True


def _guide_earnings(polygon, nodes, spans, guide):
    """Return what each skeleton node earns from the guide: the guide length nearest to it times its width.

    The guide is resampled every eighth of the typical width; samples farther than ``GUIDE_REACH``
    typical widths from the polygon are dropped.
    """
    width = typical_width(polygon.area, polygon.length / 2.0)
    reach = GUIDE_REACH * width
    west, south, east, north = polygon.bounds
    # Only the guide near the polygon counts: a long river crossing a small lake costs no more than its
    # stretch across the lake's box.
    clipped = shapely.clip_by_rect(guide, west - reach, south - reach, east + reach, north + reach)
    parts = shapely.get_parts(shapely.get_parts(clipped))
    parts = parts[shapely.get_type_id(parts) == 1]
    parts = parts[shapely.length(parts) > 0.0]
    if len(parts) == 0:
        return None
    spacing = width / 8.0
    counts = np.ceil(shapely.length(parts) / spacing).astype(np.int64)
    owner, rank = ranges(counts)
    piece = shapely.length(parts)[owner] / counts[owner]
    samples = shapely.line_interpolate_point(parts[owner], (rank + 0.5) * piece)
    shapely.prepare(polygon)
    near = shapely.dwithin(polygon, samples, reach)
    if not np.any(near):
        return None
    tree = shapely.STRtree(shapely.points(nodes))
    _, nearest = tree.query_nearest(samples[near], all_matches=False)
    return np.bincount(nearest, weights=piece[near], minlength=len(nodes)) * spans


def _on_ring(exterior, xy, tolerance):
    """Return ``xy`` moved onto the ring when it is farther than ``tolerance`` from it, CRS units.

    Back in the input's coordinates an end can lie off the ring by the rounding of coordinates far from the
    origin (a polygon 1e-5 across at 1e6, the only case where this is called): it goes to the nearest point
    of the ring, or, should rounding leave that one off too, to the nearest vertex (exactly on the ring).
    """
    point = Point(xy)
    if exterior.distance(point) <= tolerance:
        return xy
    exterior = shapely.remove_repeated_points(exterior)  # see _frames
    point = exterior.interpolate(exterior.project(point))
    if exterior.distance(point) <= tolerance:
        return np.asarray(point.coords[0])
    vertices = shapely.get_coordinates(exterior)
    return vertices[int(np.argmin(np.hypot(*(vertices - np.asarray(point.coords[0])).T)))]


def _ends_of_trunks(frames, trunks):
    """Return the :class:`EndsResult` of each frame with a trunk (None for the others), all centred together.

    Parameters
    ----------
    frames : list of _LocalPolygon or None
    trunks : list of tuple or None
        Per frame, ``(points, radii, junction, step, guided)`` in its local frame (see :func:`_joint_trunks`).

    Returns
    -------
    list of EndsResult or None
    """
    chosen = [index for index, trunk in enumerate(trunks) if trunk is not None]
    results = [None] * len(frames)
    if not chosen:
        return results
    tips = _Tips([trunks[index] for index in chosen])
    rings = _Rings(shapely.get_exterior_ring([frames[index].local for index in chosen]))
    ends = _centred_ends(tips, rings).reshape(-1, 2, 2)
    close = np.hypot(*(ends[:, 0] - ends[:, 1]).T) <= MIN_SEPARATION
    if np.any(close):
        ends[close, 1] = _opposite_points(rings.exteriors[close], rings.perimeters[close], ends[close, 0])
    diameters = 2.0 * np.maximum.reduceat(tips.radii, tips.starts)[::2]
    last = tips.starts[::2] + tips.lengths[::2] - 1
    path_lengths = tips.along[last] + tips.radii[tips.starts[::2]] + tips.radii[last]
    elongated = (diameters > 0.0) & (path_lengths >= ELONGATION_THRESHOLD * diameters)
    unguided = np.array([not trunks[index][4] for index in chosen])
    kinds = _across_centre(rings, diameters / 2.0, elongated, unguided, ends)
    backward = tips.group % 2 == 1
    # The start rule is decided in the local frame (unit diagonal), before the origin's rounding.
    east = ends[:, 1, 0] - ends[:, 0, 0]
    swap = np.where(np.abs(east) <= SAME_X, ends[:, 1, 1] < ends[:, 0, 1], east < 0.0)
    origins = np.array([frames[index].origin for index in chosen])
    scales = np.array([frames[index].scale for index in chosen])
    ends = ends * scales[:, None, None] + origins[:, None, :]
    for number in np.flatnonzero(np.max(np.abs(origins), axis=1) * np.finfo(float).eps > ON_RING * scales):
        exterior = frames[chosen[number]].polygon.exterior
        ends[number] = [_on_ring(exterior, xy, ON_RING * scales[number]) for xy in ends[number]]
    ends[swap] = ends[swap, ::-1]
    points = shapely.points(ends)
    # A trunk of one skeleton point (a ring's skeleton is a cycle without leaves) has no line.
    forward = ~backward & (tips.lengths[tips.group] > 1)
    lines = np.full(len(chosen), None, dtype=object)
    if forward.any():
        owners = tips.group[forward] // 2
        having, compact = np.unique(owners, return_inverse=True)
        lines[having] = shapely.linestrings(
            tips.points[forward] * scales[owners, None] + origins[owners], indices=compact
        )
    for number, index in enumerate(chosen):
        results[index] = EndsResult(
            start=points[number, 0],
            end=points[number, 1],
            elongated=bool(elongated[number]),
            trunk=lines[number],
            guided=trunks[index][4],
            kind=kinds[number],
        )
    return results


def _across_centre(rings, radii, elongated, unguided, ends):
    """Put the ends of compact and star-like shapes across their centre (see the module docstring, step 5).

    Parameters
    ----------
    rings : _Rings
        The exterior rings of the batch, local units.
    radii : ndarray of shape (p,)
        Largest clearance along each trunk, local units.
    elongated, unguided : ndarray of shape (p,) of bool
        Whether each shape is elongated, and whether no guide chose its path.
    ends : ndarray of shape (p, 2, 2)
        The ends centred in the trunks' caps, local units; those of compact and star-like shapes are replaced
        in place.

    Returns
    -------
    list of str
        :attr:`EndsResult.kind` of each shape.
    """
    count = len(rings.exteriors)
    kinds = [ELONGATED] * count
    outlines = shapely.polygons(rings.exteriors)
    centroids = shapely.centroid(outlines)
    xy = shapely.get_coordinates(centroids)
    clearance = np.where(shapely.contains(outlines, centroids), shapely.distance(rings.exteriors, centroids), 0.0)
    owner = np.repeat(np.arange(count), rings.lengths)
    distance = np.hypot(*(rings.vertices - xy[owner]).T)
    reach = np.maximum.reduceat(distance, rings.starts)
    candidate = unguided & (clearance > 0.0) & (reach >= STAR_ARM * clearance) & (reach <= STAR_REACH * clearance)
    for number in np.flatnonzero(candidate):
        own = slice(rings.starts[number], rings.starts[number] + rings.lengths[number])
        tips = _star_tips(outlines[number], centroids[number], clearance[number], rings.vertices[own], distance[own])
        if tips is not None:
            kinds[number], ends[number] = STAR, tips
    compact = np.flatnonzero(unguided & ~elongated & (np.array(kinds) == ELONGATED))
    if len(compact) == 0:
        return kinds
    centre = xy[compact].copy()
    for position in np.flatnonzero(clearance[compact] < 0.5 * radii[compact]):
        # The centroid lies outside the outline or near its edge: the centre of the largest inscribed disk.
        number = compact[position]
        # polylabel (Shapely 2.0) rather than maximum_inscribed_circle (2.1): the same centre, QGIS ships 2.0 too.
        centre[position] = polylabel(outlines[number], 1e-3 * radii[number]).coords[0]
    direction = _longest_axes(rings, xy, compact, centre)
    points, _, found = rings.first_crossings(
        np.concatenate([compact, compact]),
        np.concatenate([centre, centre]),
        2.0 * np.concatenate([direction, -direction]),
    )
    points = points.reshape(2, -1, 2)
    found = found.reshape(2, -1).all(axis=0)
    for position in np.flatnonzero(found):
        number = compact[position]
        kinds[number] = COMPACT
        ends[number] = points[:, position]
    return kinds


def _star_tips(outline, centre, clearance, vertices, distance):
    """Return the tips of a star-like outline's two farthest-apart arms, shape (2, 2), or None if it is not one.

    The arms are the parts of the outline beyond the disk of ``STAR_DISK`` clearances around the centre that
    reach ``STAR_ARM`` clearances from it; the outline is star-like with three or more, the third-longest
    reaching at least ``STAR_EVEN`` of the second-longest (no dominant trunk). Each arm's tip is its vertex
    farthest from the centre.

    Parameters
    ----------
    outline : Polygon
        The exterior ring's polygon, local units.
    centre : Point
        Its centroid, inside it.
    clearance : float
        The centre's distance from the ring, local units.
    vertices : ndarray of shape (m, 2)
        The ring's vertices, local units.
    distance : ndarray of shape (m,)
        Their distances from the centre, local units.
    """
    pieces = shapely.get_parts(shapely.difference(outline, shapely.buffer(centre, STAR_DISK * clearance, quad_segs=16)))
    if len(pieces) < 3:
        return None
    beyond = np.flatnonzero(distance >= STAR_ARM * clearance)
    points = shapely.points(vertices[beyond])
    tips, reaches = [], []
    for piece in pieces:
        mine = beyond[shapely.dwithin(piece, points, 1e-9)]
        if len(mine):
            tips.append(vertices[mine[np.argmax(distance[mine])]])
            reaches.append(np.max(distance[mine]))
    if len(tips) < 3 or np.sort(reaches)[-3] < STAR_EVEN * np.sort(reaches)[-2]:
        return None
    tips = np.array(tips)
    apart = np.hypot(*(tips[:, None, :] - tips[None, :, :]).transpose(2, 0, 1))
    first, second = np.unravel_index(np.argmax(apart), apart.shape)
    return tips[[first, second]]


def _longest_axes(rings, centroids, chosen, centres):
    """Return the unit direction of the longest axis of each chosen outline, shape (k, 2).

    The longest axis is the principal axis of the outline's larger second moment of area (about its
    centroid); an outline whose two moments differ by at most ``ISOTROPY`` (a square, a regular polygon) has
    none, and the direction from its centre to the nearest point of its ring (the middle of a side) is taken.

    Parameters
    ----------
    rings : _Rings
        Local units.
    centroids : ndarray of shape (p, 2)
        Centroid of each outline, local units.
    chosen : ndarray of shape (k,) of int
        The outlines wanted.
    centres : ndarray of shape (k, 2)
        The centre each axis goes through, local units.
    """
    count = len(rings.exteriors)
    owner = np.repeat(np.arange(count), rings.lengths)
    rank = np.arange(len(owner)) - rings.starts[owner]
    following = rings.starts[owner] + (rank + 1) % rings.lengths[owner]
    x, y = (rings.vertices - centroids[owner]).T
    x_next, y_next = x[following], y[following]
    cross = x * y_next - x_next * y
    xx = np.bincount(owner, cross * (x * x + x * x_next + x_next * x_next), count)[chosen]
    yy = np.bincount(owner, cross * (y * y + y * y_next + y_next * y_next), count)[chosen]
    xy = np.bincount(owner, cross * (x * y_next + 2.0 * x * y + 2.0 * x_next * y_next + x_next * y), count)[chosen]
    xy = xy / 2.0
    angle = 0.5 * np.arctan2(2.0 * xy, xx - yy)
    direction = np.stack([np.cos(angle), np.sin(angle)], axis=1)
    isotropic = np.hypot(xx - yy, 2.0 * xy) <= ISOTROPY * np.abs(xx + yy)
    if np.any(isotropic):
        nearest = _nearest_boundary_points(rings.exteriors[chosen[isotropic]], centres[isotropic])
        towards = nearest - centres[isotropic]
        direction[isotropic] = towards / np.hypot(*towards.T)[:, None]
    return direction


def _segment_sums(values, starts, lengths):
    """Return the running sums of ``values`` within each segment (``lengths[i]`` items from ``starts[i]``).

    Each segment is summed on its own and in order, as ``np.cumsum`` of it alone would be (segments of
    similar lengths are padded into one block per power of two), so a polygon's numbers do not depend on
    the other polygons of its batch.
    """
    sums = np.zeros(len(values))
    if len(values) == 0:
        return sums
    octave = np.ceil(np.log2(np.maximum(lengths, 1))).astype(np.int64)
    for level in np.unique(octave):
        rows = np.flatnonzero(octave == level)
        rank = np.arange(int(lengths[rows].max()))
        valid = rank < lengths[rows, None]
        index = np.where(valid, starts[rows, None] + rank, 0)
        block = np.cumsum(np.where(valid, values[index], 0.0), axis=1)
        sums[index[valid]] = block[valid]
    return sums


def _first_items(lengths):
    """Return the index of the first item of each group of consecutive items, from the groups' sizes."""
    return np.concatenate([[0], np.cumsum(lengths)[:-1]]).astype(np.int64)


class _Tips:
    """The trunks of a batch of polygons seen from each of their tips, as flat arrays.

    End ``2 j`` walks polygon ``j``'s trunk forward, end ``2 j + 1`` backward; each end's items are
    consecutive (``lengths[e]`` of them from ``starts[e]``).

    Attributes
    ----------
    points : ndarray of shape (n, 2)
        Trunk vertices, each polygon in its local frame.
    radii : ndarray of shape (n,)
        Clearance of each vertex, local units.
    junction : ndarray of shape (n,) of bool
        Whether each vertex is a skeleton junction.
    along : ndarray of shape (n,)
        Arc length from the end's tip, local units.
    group : ndarray of shape (n,) of int
        End of each item.
    starts, lengths : ndarray of shape (2 p,) of int
    step : ndarray of shape (2 p,)
        Densification step of each end's polygon, local units.
    """

    def __init__(self, trunks):
        sizes = np.array([len(trunk[0]) for trunk in trunks], dtype=np.int64)
        firsts = _first_items(sizes)
        points = np.concatenate([trunk[0] for trunk in trunks])
        fore = ranges(sizes)[1]
        steps = np.hypot(*(points - np.take(points, np.maximum(np.arange(len(points)) - 1, 0), axis=0)).T)
        along = _segment_sums(np.where(fore > 0, steps, 0.0), firsts, sizes)
        self.lengths = np.repeat(sizes, 2)
        self.starts = _first_items(self.lengths)
        self.group, rank = ranges(self.lengths)
        polygon = self.group // 2
        backward = self.group % 2 == 1
        source = firsts[polygon] + np.where(backward, sizes[polygon] - 1 - rank, rank)
        self.points = np.take(points, source, axis=0)
        self.radii = np.concatenate([trunk[1] for trunk in trunks])[source]
        self.junction = np.concatenate([trunk[2] for trunk in trunks])[source]
        last_along = along[firsts + sizes - 1][polygon]
        self.along = np.where(backward, last_along - along[source], along[source])
        self.step = np.repeat(np.array([trunk[3] for trunk in trunks], dtype=float), 2)

    def at(self, position, values):
        """Return ``values`` (per item) interpolated at arc length ``position`` (per end) along each end."""
        last = self.starts + self.lengths - 1
        position = np.minimum(np.maximum(position, 0.0), self.along[last])
        count = np.add.reduceat((self.along <= position[self.group]).astype(np.int64), self.starts)
        index = self.starts + np.clip(count - 1, 0, np.maximum(self.lengths - 2, 0))
        after = np.minimum(index + 1, last)
        span = self.along[after] - self.along[index]
        fraction = (position - self.along[index]) / np.where(span > 0.0, span, 1.0)
        fraction = np.where(span > 0.0, fraction, 0.0)
        if values.ndim == 2:
            fraction = fraction[:, None]
        return values[index] + fraction * (values[after] - values[index])


class _Rings:
    """The exterior rings of a batch of polygons and what the end caps need of them, computed once.

    Attributes
    ----------
    exteriors : ndarray of LinearRing
        Counter-clockwise, local units.
    perimeters : ndarray of float
    positions : ndarray of shape (m,)
        Arc length of each vertex on its ring (without the closing one and zero-length segments).
    vertices : ndarray of shape (m, 2)
        Those vertices, local units.
    starts, lengths : ndarray of int
        The items of each ring.
    """

    def __init__(self, exteriors):
        self.exteriors = exteriors
        self.perimeters = shapely.length(exteriors)
        coordinates, ring = shapely.get_coordinates(exteriors, return_index=True)
        counts = np.bincount(ring, minlength=len(exteriors))
        firsts = _first_items(counts)
        following = np.minimum(np.arange(len(ring)) + 1, len(ring) - 1)
        closing = np.arange(len(ring)) == (firsts + counts - 1)[ring]
        segment = np.where(closing, 0.0, np.hypot(*(np.take(coordinates, following, axis=0) - coordinates).T))
        before = np.where(np.arange(len(ring)) == firsts[ring], 0.0, segment[np.arange(len(ring)) - 1])
        positions = _segment_sums(before, firsts, counts)
        keep = ~closing & (segment > 0.0)
        self.positions = positions[keep]
        self.lengths = np.bincount(ring[keep], minlength=len(exteriors))
        self.starts = _first_items(self.lengths)
        self.vertices = coordinates[keep]
        # Each ring's positions lifted above the previous rings' (by their perimeters and a margin), one
        # increasing array for all: a ring's positions are found with one search.
        self._base = np.cumsum(self.perimeters + 1.0) - (self.perimeters + 1.0)
        self._lifted = self.positions + np.repeat(self._base, self.lengths)
        # Far above the rounding of a lifted position (a few ulps of the batch's summed perimeters).
        self._margin = 1e-6 + 64.0 * np.finfo(float).eps * float(np.sum(self.perimeters + 1.0))

    def arc_vertices(self, ring, start, length):
        """Return the vertices near the arcs of given rings (within 1e-6 local units), and the arc of each.

        Parameters
        ----------
        ring : ndarray of shape (k,) of int
            Ring of each arc.
        start, length : ndarray of shape (k,)
            Where each arc begins on its ring and its length (at most the perimeter), local units.

        Returns
        -------
        vertex : ndarray of int
            Vertices (into ``positions``), arc after arc, each from the arc's start on (wrapping around the
            ring); a superset of those whose position lies strictly within the arc.
        arc : ndarray of int
            Arc of each of them.
        """
        lengths = self.lengths[ring]
        low = self._count_below(ring, start - self._margin)
        high = self._count_below(ring, start + length + self._margin)
        arc, rank = ranges(np.minimum(high - low + 1, lengths))
        return self.starts[ring][arc] + (low[arc] + rank) % lengths[arc], arc

    def _count_below(self, ring, position):
        """Return how many vertices of each ring lie before ``position`` on it, counted around the ring
        (plus its vertex count per turn beyond the perimeter, less it per turn before zero)."""
        turns = np.floor(position / self.perimeters[ring])
        within = position - turns * self.perimeters[ring]
        below = np.searchsorted(self._lifted, within + self._base[ring]) - self.starts[ring]
        return below + turns.astype(np.int64) * self.lengths[ring]

    def first_crossings(self, ring, origin, direction):
        """Return where each ray first meets its ring: the point, its arc length on the ring, and whether it does.

        A ray runs from ``origin`` to ``origin + direction``; it meets a segment whose ends lie on both sides
        of the ray's line or on it (each vertex's side is computed once per ray, so no ray slips between two
        segments at their shared vertex), or, when both ends lie on the line, at the segment's point nearest
        to ``origin``. The crossing nearest to ``origin`` along the ray is kept (the first segment's on a tie).

        Parameters
        ----------
        ring : ndarray of shape (k,) of int
            Ring of each ray.
        origin, direction : ndarray of shape (k, 2)
            Local units.

        Returns
        -------
        points : ndarray of shape (k, 2)
            The first crossing (``origin`` where there is none), local units.
        positions : ndarray of shape (k,)
            Its arc length on the ring (0 where there is none), local units.
        found : ndarray of shape (k,) of bool
        """
        sizes = self.lengths[ring]
        ray, rank = ranges(sizes)
        size = np.repeat(sizes, sizes)
        vertex = np.repeat(self.starts[ring], sizes) + rank
        x, y = np.take(self.vertices, vertex, axis=0).T
        along_x, along_y = direction.T
        # Each vertex's side of its ray's line: the cross product of the direction with (vertex - origin).
        side = np.repeat(along_x, sizes) * y - np.repeat(along_y, sizes) * x
        side -= np.repeat(along_x * origin[:, 1] - along_y * origin[:, 0], sizes)
        following = np.arange(len(rank)) + np.where(rank + 1 == size, 1 - size, 1)
        side_after = side[following]
        crossing = np.sign(side) != np.sign(side_after)
        on_line = (side == 0.0) & (side_after == 0.0)
        pair = np.flatnonzero(crossing | on_line)
        ray, crossing, on_line = ray[pair], crossing[pair], on_line[pair]
        start = np.take(self.vertices, vertex[pair], axis=0)
        segment = np.take(self.vertices, vertex[following[pair]], axis=0) - start
        corner = start - origin[ray]
        squared = np.einsum("ij,ij->i", segment, segment)
        nearest = np.clip(-np.einsum("ij,ij->i", corner, segment) / np.where(squared > 0.0, squared, 1.0), 0.0, 1.0)
        through = side[pair] / np.where(crossing, side[pair] - side_after[pair], 1.0)
        fraction = np.where(on_line, nearest, through)
        offset = corner + fraction[:, None] * segment
        reach = np.einsum("ij,ij->i", offset, direction[ray]) / np.einsum("ij,ij->i", direction, direction)[ray]
        met = np.flatnonzero((reach >= 0.0) & (reach <= 1.0))
        points, positions = origin.copy(), np.zeros(len(ring))
        found = np.zeros(len(ring), dtype=bool)
        if len(met):
            ordered = met[np.lexsort((reach[met], ray[met]))]
            chosen = ordered[np.append(True, ray[ordered][1:] != ray[ordered][:-1])]
            points[ray[chosen]] = origin[ray[chosen]] + offset[chosen]
            arc = self.positions[vertex[pair[chosen]]] + fraction[chosen] * np.sqrt(squared[chosen])
            positions[ray[chosen]] = arc
            found[ray[chosen]] = True
        return points, positions, found

    def turns(self, vertex):
        """Return the signed turn of the rings at ``vertex`` (into ``positions``), radians (positive to the
        left)."""
        owner = np.searchsorted(self.starts, vertex, side="right") - 1
        size = np.maximum(self.lengths[owner], 1)
        rank = vertex - self.starts[owner]
        incoming = self.vertices[vertex] - np.take(self.vertices, self.starts[owner] + (rank - 1) % size, axis=0)
        outgoing = np.take(self.vertices, self.starts[owner] + (rank + 1) % size, axis=0) - self.vertices[vertex]
        return turns_between(incoming, outgoing)


def _last_trunk_positions(tips):
    """Return the arc length of each end's last trunk point ``T`` (see the module docstring, step 3).

    ``T`` is the widest skeleton junction within ``CAP_WINDOW`` radii of the tip (the first such on a tie);
    without one, the point where ``d`` first exceeds ``CAP_REACH * r``; at most half the path.
    """
    along, radii = tips.along, tips.radii
    travelled = radii[tips.starts][tips.group] + along
    half = along[tips.starts + tips.lengths - 1] / 2.0
    within = along <= half[tips.group]
    candidate = tips.junction & (travelled <= CAP_WINDOW * radii) & within
    index = np.arange(len(along))
    widest_radius = np.maximum.reduceat(np.where(candidate, radii, -np.inf), tips.starts)
    widest = np.minimum.reduceat(
        np.where(candidate & (radii == widest_radius[tips.group]), index, len(along)), tips.starts
    )
    has_junction = widest < len(along)
    widest = np.minimum(widest, len(along) - 1)
    excess = travelled - CAP_REACH * radii
    first = np.minimum.reduceat(np.where((excess > 0.0) & within, index, len(along)), tips.starts)
    inside = np.minimum(first, len(along) - 1)
    before = np.maximum(inside - 1, 0)
    rise = excess[inside] - excess[before]
    crossing = along[before] + (along[inside] - along[before]) * -excess[before] / np.where(rise != 0.0, rise, 1.0)
    position = np.where(first == len(along), half, np.where(first == tips.starts, 0.0, crossing))
    return np.where(has_junction, along[widest], position)


def _centred_ends(tips, rings):
    """Return each end centred in its end cap (see the module docstring, step 3), shape (2 p, 2), local units."""
    owner = np.arange(len(tips.starts)) // 2
    exteriors = rings.exteriors[owner]
    position = _last_trunk_positions(tips)
    radius = np.maximum(tips.at(position, tips.radii), tips.step)
    point = tips.at(position, tips.points)
    chord = point - tips.at(position + np.maximum(radius, 2.0 * tips.step), tips.points)
    flat = ~np.any(chord, axis=1)
    chord[flat] = (tips.points[tips.starts] - point)[flat]
    stuck = ~np.any(chord, axis=1) | (tips.lengths < 2)
    chord[stuck] = (1.0, 0.0)
    chord = chord / np.hypot(*chord.T)[:, None]
    normal = np.stack([-chord[:, 1], chord[:, 0]], axis=1)
    offset = radius[:, None] * normal
    left, right = _nearest_boundary_points(
        np.tile(exteriors, 2), np.concatenate([point + offset, point - offset])
    ).reshape(2, -1, 2)
    tangent = np.stack([left[:, 1] - right[:, 1], right[:, 0] - left[:, 0]], axis=1)
    tangent_norm = np.hypot(*tangent.T)
    sign = np.sign(np.einsum("ij,ij->i", tangent, chord))
    sign[sign == 0.0] = 1.0
    tangent = tangent / np.where(tangent_norm > 0.0, tangent_norm, 1.0)[:, None] * sign[:, None]
    tangent[tangent_norm <= 1e-9] = chord[tangent_norm <= 1e-9]
    exit_points, at_exit, found = rings.first_crossings(owner, point, tangent * 2.0)
    ends = _cap_middles(rings, owner, left, right, exit_points, at_exit)
    fallback = stuck | ~found
    if np.any(fallback):
        ends[fallback] = _nearest_boundary_points(exteriors[fallback], point[fallback])
    return ends


def _cap_middles(rings, owner, left, right, exit_points, at_exit):
    """Return the middle of each end cap: the ring arc from ``right`` to ``left`` through the exit point.

    Corners are the arc's vertices where a counter-clockwise ring turns left by ``CORNER_TURN`` or more.
    With two or more corners (a flat or oblique cut) the end is the arc-length midpoint between the first
    and the last corner; with one (a pointed end) it is that corner; with none (a rounded cap) it is the
    arc-length midpoint of the whole arc; the exit point itself when the arc is more than half the ring.

    Parameters
    ----------
    rings : _Rings
    owner : ndarray of int
        Ring of each end.
    left, right, exit_points : ndarray of shape (k, 2)
        Where each end's last trunk disk touches the two banks, and where the trunk's continuation leaves
        the polygon, local units.
    at_exit : ndarray of shape (k,)
        Arc length of each exit point on its ring, local units.

    Returns
    -------
    ndarray of shape (k, 2)
        Local units.
    """
    exteriors, perimeter = rings.exteriors[owner], rings.perimeters[owner]
    located = shapely.line_locate_point(np.tile(exteriors, 2), shapely.points(np.concatenate([left, right])))
    at_left, at_right = located.reshape(2, -1)
    forward = (at_left - at_right) % perimeter
    through = (at_exit - at_right) % perimeter <= forward
    start = np.where(through, at_right, at_left)
    length = np.where(through, forward, perimeter - forward)
    vertex, end = rings.arc_vertices(owner, start, length)
    offset = (rings.positions[vertex] - start[end]) % perimeter[end]
    within = np.flatnonzero((offset > 0.0) & (offset < length[end]))
    vertex, end, offset = vertex[within], end[within], offset[within]
    corner = rings.turns(vertex) >= CORNER_TURN
    corner_count = np.bincount(end[corner], minlength=len(owner))
    low = np.full(len(owner), np.inf)
    high = np.full(len(owner), -np.inf)
    np.minimum.at(low, end[corner], offset[corner])
    np.maximum.at(high, end[corner], offset[corner])
    target = length / 2.0
    target[corner_count == 1] = low[corner_count == 1]
    several = corner_count > 1
    target[several] = (low[several] + high[several]) / 2.0
    middles = shapely.get_coordinates(shapely.line_interpolate_point(exteriors, (start + target) % perimeter))
    too_long = length > perimeter / 2.0
    middles[too_long] = exit_points[too_long]
    return middles


def _opposite_points(exteriors, perimeters, xy):
    """Return the points of the rings half their perimeter along from the points nearest to ``xy``."""
    position = shapely.line_locate_point(exteriors, shapely.points(xy)) + perimeters / 2.0
    return shapely.get_coordinates(shapely.line_interpolate_point(exteriors, position % perimeters))


def _nearest_boundary_points(exteriors, xy):
    """Return the point of each ring ``exteriors`` nearest to each of the points ``xy`` (shape (n, 2))."""
    return shapely.get_coordinates(shapely.shortest_line(shapely.points(xy), exteriors))[1::2]


class PolygonSkeleton:
    """A polygon's skeleton as :func:`find_ends` builds it, for a caller that walks it itself (:mod:`.arms`).

    The polygon is moved to its local frame (origin at its box centre, unit bounding-box diagonal; islands
    smaller than its typical width left out) and triangulated once; :meth:`main_stem` and :meth:`trunk_ends`
    then apply :func:`find_ends`'s own rules to that skeleton.

    Parameters
    ----------
    polygon : Polygon
        A valid polygon, CRS units.
    every_island : bool
        Keep every island in the skeleton, also those smaller than the typical width (a road grid's blocks).

    Attributes
    ----------
    origin : ndarray of shape (2,)
        Centre of the polygon's bounding box, CRS units.
    scale : float
        Its bounding-box diagonal, CRS units (one local unit).
    local : Polygon
        The polygon in the local frame, counter-clockwise.
    skeleton : Skeletons
        Its :func:`.skeleton.joint_skeletons` (one polygon), local units.

    Raises
    ------
    InvalidGeometryError
        As :func:`find_ends` (an invalid, absurdly scaled or untriangulable polygon).
    """

    def __init__(self, polygon, *, every_island=False):
        self.origin, self.scale = _local_box(polygon, None)
        (self._frame,) = _frames([polygon], [None], [(self.origin, self.scale)], every_island)
        self.local = self._frame.local
        self.skeleton = joint_skeletons([self.local])
        if self.skeleton.errors[0] is not None:
            raise self.skeleton.errors[0]

    def main_stem(self):
        """Return the :class:`EndsResult` :func:`find_ends` gives for the polygon (rule ``"main_stem"``)."""
        outcomes = [None]
        trunks = _joint_trunks([self._frame], "main_stem", outcomes, _no_check, skeleton=self.skeleton)
        if outcomes[0] is not None:
            raise outcomes[0]
        return _ends_of_trunks([self._frame], trunks)[0]

    def trunk_ends(self, trunks):
        """Return the first end of each trunk centred in its end cap (step 3 of the module docstring).

        Parameters
        ----------
        trunks : list of tuple
            Per end, ``(points, radii, junction, step)``: the skeleton path from the tip inward (local
            units), each point's clearance (local units), whether it is a skeleton junction, and the
            skeleton's densification step (local units).

        Returns
        -------
        ndarray of shape (len(trunks), 2)
            The ends on the exterior ring, CRS units.
        """
        tips = _Tips([(*trunk, False) for trunk in trunks])
        rings = _Rings(np.array([self.local.exterior] * len(trunks), dtype=object))
        points = _centred_ends(tips, rings)[::2] * self.scale + self.origin
        if np.max(np.abs(self.origin)) * np.finfo(float).eps > ON_RING * self.scale:
            exterior = self._frame.polygon.exterior
            points = np.array([_on_ring(exterior, xy, ON_RING * self.scale) for xy in points])
        return points.reshape(-1, 2)
