"""Typed errors of the geometry core, and every message the core gives the user.

Every error the core raises on bad input is an :class:`IncirCuError`, so a caller can catch one class. The
message is written for the person who owns the data: it says what is wrong and, where it helps, where.

Each message is a :class:`Message`: the English text of a template of :data:`MESSAGES` filled with its values,
which keeps its ``code`` and ``values``, so a caller can word it in another language (the QGIS plugin formats the
translated template with the same values; lengths name their unit through the ``units`` value, "CRS units"
here). A new message is one line in :data:`MESSAGES` and ``raise SomeError(Message("code", value=...))``.
"""


# Named as Qt's macro: pylupdate5 collects the texts given to a function of this name.
def QT_TRANSLATE_NOOP(context, text):
    """Return ``text``; marks it for Qt's ``pylupdate5``, which collects the plugin's texts to translate."""
    return text


#: The translation context of the core's messages.
CONTEXT = "IncirCuCore"
#: Values every message may name: the unit of its lengths and QGIS's tool that repairs geometries.
DEFAULT_VALUES = {"units": "CRS units", "fix_geometries": "Fix geometries"}

#: Every message of the core by code: an English template of ``str.format`` fields. Fields holding a
#: :class:`Message` (a noun such as "the first line") are worded in the caller's language too.
# fmt: off
# (No comma after a template: pylupdate5 would not read the call.)
MESSAGES = {
    # Nouns filled in as {name} or {subject}.
    "noun_polygon": QT_TRANSLATE_NOOP("IncirCuCore", "polygon"),
    "noun_exterior_ring": QT_TRANSLATE_NOOP("IncirCuCore", "exterior ring"),
    "noun_pair_of_lines": QT_TRANSLATE_NOOP("IncirCuCore", "pair of lines"),
    "noun_first_line": QT_TRANSLATE_NOOP("IncirCuCore", "first line"),
    "noun_second_line": QT_TRANSLATE_NOOP("IncirCuCore", "second line"),
    "noun_first_chain": QT_TRANSLATE_NOOP("IncirCuCore", "first chain"),
    "noun_second_chain": QT_TRANSLATE_NOOP("IncirCuCore", "second chain"),
    "noun_split_points": QT_TRANSLATE_NOOP("IncirCuCore", "split points"),
    "noun_line": QT_TRANSLATE_NOOP("IncirCuCore", "line"),
    "noun_chain": QT_TRANSLATE_NOOP("IncirCuCore", "chain"),
    "subject_polygon": QT_TRANSLATE_NOOP("IncirCuCore", "The polygon"),
    "subject_part": QT_TRANSLATE_NOOP("IncirCuCore", "The part"),
    "split_point_one": QT_TRANSLATE_NOOP("IncirCuCore", "split point"),
    "split_point_many": QT_TRANSLATE_NOOP("IncirCuCore", "split points"),
    "needs_two_or_fewer": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "it needs 2 (or fewer, to find the missing ends automatically); with 3 or more ends (a confluence, or a "
        "reach touching 3 others) it is a network: compute its centerline network instead"
    ),
    "network_needs_two": QT_TRANSLATE_NOOP("IncirCuCore", "a network needs at least 2"),
    # Options.
    "unknown_island_mode": QT_TRANSLATE_NOOP("IncirCuCore", "Unknown island mode {mode!r}; use one of {choices}."),
    "unknown_end_rule": QT_TRANSLATE_NOOP("IncirCuCore", "Unknown end rule {rule!r}; use one of {choices}."),
    "option_not_length": QT_TRANSLATE_NOOP(
        "IncirCuCore", "{name} must be a number (a length in {units}), got {value!r}."
    ),
    "option_bad_length": QT_TRANSLATE_NOOP(
        "IncirCuCore", "{name} must be a positive, finite length in {units} (or 0 for automatic), got {value!r}."
    ),
    "option_bad_distance": QT_TRANSLATE_NOOP(
        "IncirCuCore", "{name} must be a non-negative, finite distance in {units} (or None), got {value!r}."
    ),
    "option_not_number": QT_TRANSLATE_NOOP("IncirCuCore", "{name} must be a number, got {kind} {value!r}."),
    "label_option_not_number": QT_TRANSLATE_NOOP(
        "IncirCuCore", "The label option {name} must be a number ({what}), not {value!r}."
    ),
    "label_option_out_of_range": QT_TRANSLATE_NOOP(
        "IncirCuCore", "The label option {name} is {value!r}; it must be {what}."
    ),
    "label_range_share_of_widest": QT_TRANSLATE_NOOP(
        "IncirCuCore", "a share of the widest width, at least 0 and under 1"
    ),
    "label_range_clearance": QT_TRANSLATE_NOOP(
        "IncirCuCore", "a share of the local width, at least 0 and under 0.5 (the middle)"
    ),
    "label_range_share_of_width": QT_TRANSLATE_NOOP("IncirCuCore", "a share of the local width, at least 0"),
    "label_range_ratio": QT_TRANSLATE_NOOP("IncirCuCore", "a ratio, at least 0"),
    "samples_not_whole": QT_TRANSLATE_NOOP("IncirCuCore", "samples_per_chain must be a whole number, got {value!r}."),
    "samples_too_few": QT_TRANSLATE_NOOP(
        "IncirCuCore", "The number of samples per chain must be at least 1, got {value!r}."
    ),
    "spacing_too_small": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "A spacing of {spacing:.6g} would need about {planned:.3g} samples (at most {limit:.3g}); use a larger spacing."
    ),
    "values_per_geometry": QT_TRANSLATE_NOOP(
        "IncirCuCore", "{name} has {given} values for {count} geometries; give one value or one per geometry."
    ),
    "tolerance_and_spacing": QT_TRANSLATE_NOOP(
        "IncirCuCore", "Give either a tolerance (adaptive sampling) or a spacing / sample count (fixed sampling)."
    ),
    "tolerance_too_fine": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "The tolerance {tolerance:.6g} ({units}) you set is below {relative:g} of the shape's extent "
        "({extent:.6g} {units}): float64 cannot place vertices that finely. Use at least {least:.3g} ({units}), or "
        "0 for the automatic tolerance."
    ),
    "note_tolerance_finest": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "The shape is {width:.3g} {units} wide, {relative:.3g} of its extent ({extent:.6g} {units}): its automatic "
        "tolerance (the width / 200) is finer than float64 can place vertices, so the finest possible, "
        "{finest:.3g} {units} ({minimum:g} of the extent), is used."
    ),
    "region_too_narrow": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "The shape is {width:.3g} {units} wide (its area over its length), {relative:.3g} of its extent "
        "({extent:.6g} {units}), under the {minimum:g} at which float64 can still tell its two sides apart: no "
        "centerline can be traced. At this width its sides are the centerline: use one of them."
    ),
    "circle_segments": QT_TRANSLATE_NOOP(
        "IncirCuCore", "A circle needs at least 1 segment per quarter, got {value!r}."
    ),
    "transect_interval_kind": QT_TRANSLATE_NOOP(
        "IncirCuCore", "The transect interval must be a distance, got {value!r}."
    ),
    "transect_interval_positive": QT_TRANSLATE_NOOP(
        "IncirCuCore", "The transect interval must be a positive distance, got {value!r}."
    ),
    "guides_count": QT_TRANSLATE_NOOP("IncirCuCore", "{guides} guides were given for {polygons} polygons."),
    "unknown_end_cap": QT_TRANSLATE_NOOP("IncirCuCore", "Unknown end cap {cap!r}; use one of {choices}."),
    "unknown_transect_style": QT_TRANSLATE_NOOP(
        "IncirCuCore", "Unknown transect style {style!r}; use one of {choices}."
    ),
    "arm_ratio_bad": QT_TRANSLATE_NOOP(
        "IncirCuCore", "min_arm_ratio must be a finite number >= 0, got {value!r}."
    ),
    "arm_length_bad": QT_TRANSLATE_NOOP(
        "IncirCuCore", "min_arm_length must be a finite length >= 0 ({units}), got {value!r}."
    ),
    # Geometries.
    "polygon_null": QT_TRANSLATE_NOOP("IncirCuCore", "The polygon is null (no geometry)."),
    "polygon_empty": QT_TRANSLATE_NOOP("IncirCuCore", "The polygon is empty."),
    "not_polygon_or_multi": QT_TRANSLATE_NOOP("IncirCuCore", "Expected a polygon or multipolygon, got a {kind}."),
    "not_polygon": QT_TRANSLATE_NOOP("IncirCuCore", "Expected a single polygon, got a {kind}."),
    "polygon_invalid": QT_TRANSLATE_NOOP(
        "IncirCuCore", "The polygon is not valid: {reason}. Repair it first (e.g. QGIS '{fix_geometries}')."
    ),
    "named_null": QT_TRANSLATE_NOOP("IncirCuCore", "The {name} is null (no geometry)."),
    "named_empty": QT_TRANSLATE_NOOP("IncirCuCore", "The {name} is empty."),
    "not_single_line": QT_TRANSLATE_NOOP("IncirCuCore", "The {name} must be a single line, not a {kind}."),
    "not_number_array": QT_TRANSLATE_NOOP("IncirCuCore", "The {name} must be an (n, 2) array of numbers."),
    "not_coordinate_array": QT_TRANSLATE_NOOP("IncirCuCore", "The {name} must be an (n, 2) coordinate array."),
    "not_finite": QT_TRANSLATE_NOOP("IncirCuCore", "The {name} has a NaN or infinite coordinate: {value}."),
    "coordinate_too_large": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "The {name} has a coordinate of magnitude {magnitude:.3g}, beyond {limit:.0e}: products of such coordinates "
        "overflow float64. Use a projected CRS in metres, or scale the data down."
    ),
    "extent_too_small": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "The {name} is {extent:.3g} across, under {limit:.0e}: products of its lengths underflow float64. Scale the "
        "data up (use smaller units)."
    ),
    "extent_too_small_here": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "The {name} is {extent:.3g} across at coordinates of magnitude {magnitude:.3g}: float64 cannot resolve a "
        "shape smaller than {limit:.0e} of its distance from the origin. Shift the data nearer the origin (subtract "
        "an offset) or use a local projected CRS."
    ),
    "polygon_size_absurd": QT_TRANSLATE_NOOP(
        "IncirCuCore", "The polygon's size ({size:.3g}) is absurd for its coordinates' units; reproject or rescale it."
    ),
    "too_many_segments": QT_TRANSLATE_NOOP(
        "IncirCuCore", "The boundary has {count:,} segments, more than this engine can index."
    ),
    "guide_kind": QT_TRANSLATE_NOOP("IncirCuCore", "A guide must be a line or multiline, got a {kind}."),
    "guide_not_finite": QT_TRANSLATE_NOOP("IncirCuCore", "The guide line has a NaN or infinite coordinate."),
    "island_not_finite": QT_TRANSLATE_NOOP(
        "IncirCuCore", "Island {index} is empty or has a NaN or infinite coordinate."
    ),
    "island_too_few_points": QT_TRANSLATE_NOOP("IncirCuCore", "Island {index} has fewer than 3 distinct points."),
    "centre_null": QT_TRANSLATE_NOOP("IncirCuCore", "Cannot centre a projection on a null geometry."),
    "centre_empty": QT_TRANSLATE_NOOP("IncirCuCore", "Cannot centre a projection on an empty geometry."),
    "centre_not_finite": QT_TRANSLATE_NOOP(
        "IncirCuCore", "Cannot centre a projection on a geometry with a NaN or infinite coordinate."
    ),
    "centre_not_degrees": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "The projection centre ({longitude!r}, {latitude!r}) is not a longitude and a latitude in degrees."
    ),
    "point_not_projected": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "A point could not be projected (a NaN or infinite coordinate, or a latitude beyond 90 degrees)."
    ),
    "unknown_crs": QT_TRANSLATE_NOOP("IncirCuCore", "Unknown CRS {crs!r}: {error}"),
    "not_geographic_crs": QT_TRANSLATE_NOOP("IncirCuCore", "{name} is not a geographic CRS."),
    # Chains and lines.
    "chain_too_few_points": QT_TRANSLATE_NOOP("IncirCuCore", "The {name} has fewer than 2 distinct points."),
    "chain_folds": QT_TRANSLATE_NOOP("IncirCuCore", "The {name} folds back over itself at {point}."),
    "chain_crosses": QT_TRANSLATE_NOOP("IncirCuCore", "The {name} crosses itself at {point}."),
    "lines_cross": QT_TRANSLATE_NOOP(
        "IncirCuCore", "The two lines cross or touch at {point}; they must bound a region between them."
    ),
    "chains_cross": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "The two chains cross or touch at {point}; they must bound a region between them, meeting at most at "
        "shared end points."
    ),
    "lines_no_area": QT_TRANSLATE_NOOP(
        "IncirCuCore", "The two lines enclose no area between them (they lie on one line)."
    ),
    "chains_too_close": QT_TRANSLATE_NOOP(
        "IncirCuCore", "The chains are too close together or too short to carry a centerline."
    ),
    "first_line_longer": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "The first line is {length:.6g} long, {ratio:.3g} times the second one ({other:.6g} {units}): it runs on "
        "beyond the other, where the region between them is closed by the straight gap between their ends, and the "
        "centerline follows that gap there. Cut the lines to where they face each other."
    ),
    "second_line_longer": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "The second line is {length:.6g} long, {ratio:.3g} times the first one ({other:.6g} {units}): it runs on "
        "beyond the other, where the region between them is closed by the straight gap between their ends, and the "
        "centerline follows that gap there. Cut the lines to where they face each other."
    ),
    # Zero-width spikes removed: the note names up to three places, each a spike_* message.
    "note_spike_one": QT_TRANSLATE_NOOP(
        "IncirCuCore", "A zero-width spike was removed from {places} before the centerline was computed."
    ),
    "note_spikes": QT_TRANSLATE_NOOP(
        "IncirCuCore", "{count} zero-width spikes were removed from {places} before the centerline was computed."
    ),
    "spike_exterior": QT_TRANSLATE_NOOP(
        "IncirCuCore", "the exterior ring at {point} ({length:.6g} {units} long)"
    ),
    "spike_island": QT_TRANSLATE_NOOP("IncirCuCore", "island {number} at {point} ({length:.6g} {units} long)"),
    "spike_first_line": QT_TRANSLATE_NOOP("IncirCuCore", "the first line at {point} ({length:.6g} {units} long)"),
    "spike_second_line": QT_TRANSLATE_NOOP(
        "IncirCuCore", "the second line at {point} ({length:.6g} {units} long)"
    ),
    "places_two": QT_TRANSLATE_NOOP("IncirCuCore", "{first}; {second}"),
    "places_three": QT_TRANSLATE_NOOP("IncirCuCore", "{first}; {second}; {third}"),
    "places_more": QT_TRANSLATE_NOOP("IncirCuCore", "{first}; {second}; {third}; and {more} more"),
    # Split points and ends.
    "split_point_far": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "Split point {point} is {distance:.6g} {units} away from the polygon's boundary; the snap tolerance is "
        "{tolerance:.6g} {units}. Move the point onto the boundary or raise the tolerance."
    ),
    "split_point_count": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "{subject} has {count} {points} within the snap tolerance ({tolerance:.6g} {units}) of its exterior ring; "
        "{needed}."
    ),
    "split_points_not_two": QT_TRANSLATE_NOOP(
        "IncirCuCore", "A polygon needs exactly 2 split points on its boundary, got {count}."
    ),
    "split_points_same_place": QT_TRANSLATE_NOOP(
        "IncirCuCore", "Both split points snap to the same place {point} of the boundary."
    ),
    "split_points_kind": QT_TRANSLATE_NOOP(
        "IncirCuCore", "Split points must be a sequence of two points (or a MultiPoint), got a {kind}."
    ),
    "split_point_empty": QT_TRANSLATE_NOOP("IncirCuCore", "Split point {index} is an empty point."),
    "split_point_kind": QT_TRANSLATE_NOOP("IncirCuCore", "Split point {index} must be a point, not a {kind}."),
    "split_point_number": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "Split point {index} is the number {value!r}: give a sequence of points, such as [(x1, y1), (x2, y2)]."
    ),
    "split_point_pair": QT_TRANSLATE_NOOP(
        "IncirCuCore", "Split point {index} must be an (x, y) pair of numbers, got {value!r}."
    ),
    "split_point_not_finite": QT_TRANSLATE_NOOP("IncirCuCore", "A split point has a NaN or infinite coordinate."),
    "ends_coincide": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "The ends found automatically coincide at {point}: the shape has no clear ends. Give two split points."
    ),
    "ends_geos": QT_TRANSLATE_NOOP("IncirCuCore", "The ends of the polygon cannot be found: {error}."),
    "ends_too_thin": QT_TRANSLATE_NOOP(
        "IncirCuCore", "The polygon is too thin or too small to find its ends automatically; give two split points."
    ),
    "ends_too_narrow": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "The polygon is {width:.3g} {units} wide (its area over half its perimeter), {relative:.3g} of its extent "
        "({extent:.6g} {units}), under the {minimum:g} at which its ends can be found automatically in float64; "
        "give two split points."
    ),
    "arms_too_thin": QT_TRANSLATE_NOOP(
        "IncirCuCore", "The polygon is too thin or too small to find its arms automatically."
    ),
    "arm_ends_too_few": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "Only {count} arm end was found automatically on this polygon; give its ends as split points."
    ),
    "gates_failed": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "The boundary this feature shares with the features it touches could not be computed ({reason}): it is "
        "not connected to them. Repair it first (e.g. QGIS '{fix_geometries}')."
    ),
    "outline_not_triangulated": QT_TRANSLATE_NOOP(
        "IncirCuCore", "The polygon's outline could not be triangulated to find its ends automatically."
    ),
    "note_guide_far": QT_TRANSLATE_NOOP(
        "IncirCuCore", "The guide line does not come near the polygon; its ends were found automatically."
    ),
    "note_not_elongated": QT_TRANSLATE_NOOP(
        "IncirCuCore", "The shape is not elongated; its automatically found ends are arbitrary."
    ),
    "note_star": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "The shape is star-like, with no dominant trunk; its automatic ends are the tips of its two "
        "farthest-apart arms."
    ),
    "note_compact": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "The shape is not elongated, with no dominant trunk; its automatic ends lie across its centre, "
        "along its longest axis."
    ),
    "note_ring": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "The polygon is a ring around one island: its centerline is the closed loop around the island, from and "
        "back to the ring's narrowest place. Give two split points for a line between them."
    ),
    "note_ring_point_unused": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "The polygon is a ring around one island: its centerline is the closed loop around the island, from and "
        "back to the ring's narrowest place; the one split point given is not used. Give two split points for a "
        "line between them."
    ),
    # Islands.
    "island_blocked": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "The island at {point} cannot be joined to a bank without crossing another island; use the option to "
        "ignore islands."
    ),
    # Computed lines.
    "centerline_not_finite": QT_TRANSLATE_NOOP(
        "IncirCuCore", "The computed centerline has a NaN or infinite coordinate; none is returned."
    ),
    "centerline_crosses": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "The computed centerline crosses itself, so none is returned. This happens where the shape has no single "
        "axis near the ends (a compact shape, or a split point in a corner): move the split points to the middle of "
        "the ends, or change the spacing."
    ),
    "centerline_crosses_at": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "The computed centerline crosses itself at {point}, so none is returned. This happens where the shape has "
        "no single axis near the ends (a compact shape, or a split point in a corner): move the split points to the "
        "middle of the ends, or change the spacing."
    ),
    "centerline_leaves": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "The computed centerline leaves the polygon at {point} ({outside:.6g} outside), so none is returned. Give "
        "split points, or change the tolerance."
    ),
    # Networks.
    "network_too_few_points": QT_TRANSLATE_NOOP(
        "IncirCuCore", "A network needs at least 2 split points on the boundary, got {count}."
    ),
    "network_same_place": QT_TRANSLATE_NOOP(
        "IncirCuCore", "Two split points snap to the same place {point} of the boundary."
    ),
    "network_order": QT_TRANSLATE_NOOP(
        "IncirCuCore", "The split points could not be placed in order on the boundary with its islands."
    ),
    "junction_out_of_order": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "The junction near {point} could not be located: its circle holds another chain out of order. Move the "
        "split points farther out along the arms."
    ),
    "junction_several_contacts": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "The junction near {point} could not be located: its circle touches a chain at several places or a split "
        "point itself. Move the split points farther out along the arms."
    ),
    "branch_too_short": QT_TRANSLATE_NOOP(
        "IncirCuCore", "A branch of the network has fewer than 2 vertices; try a smaller spacing."
    ),
    "network_not_tree": QT_TRANSLATE_NOOP(
        "IncirCuCore",
        "The network found is not a tree with one end at each of the {k} split points ({branches} branches, "
        "{ends} ends, {weak} junctions of degree below 3); a split point may lie on a junction's circle: move the "
        "split points farther out along the arms."
    ),
}
# fmt: on

#: The noun of each ``name`` the core's functions take for what they check ("first line"...).
NOUNS = {
    "polygon": "noun_polygon",
    "exterior ring": "noun_exterior_ring",
    "pair of lines": "noun_pair_of_lines",
    "first line": "noun_first_line",
    "second line": "noun_second_line",
    "first chain": "noun_first_chain",
    "second chain": "noun_second_chain",
    "split points": "noun_split_points",
    "line": "noun_line",
    "chain": "noun_chain",
}


class Message(str):
    """A message for the user: the English text of template ``MESSAGES[code]`` filled with ``values``.

    It is a ``str`` (its English text) that keeps ``code`` and ``values`` (with :data:`DEFAULT_VALUES`), so a
    caller can fill the same template in another language.

    Examples
    --------
    >>> note = Message("island_too_few_points", index=2)
    >>> note, note.code, note.values["index"]
    ('Island 2 has fewer than 3 distinct points.', 'island_too_few_points', 2)
    """

    def __new__(cls, code, **values):
        values = {**DEFAULT_VALUES, **values}
        text = super().__new__(cls, MESSAGES[code].format(**values))
        text.code = code
        text.values = values
        return text

    def __reduce__(self):
        return _message, (self.code, self.values)


def _message(code, values):
    """Rebuild a :class:`Message` (for pickling)."""
    return Message(code, **values)


def noun(name):
    """Return ``name`` (what a check calls its input: "first line"...) as a :class:`Message`, so it is worded in
    the caller's language; a name without a noun in :data:`NOUNS` stays as it is."""
    return Message(NOUNS[name]) if name in NOUNS else name


class Cancelled(Exception):
    """Raised when the progress callback asks the engine to stop (not an error of the input)."""


class IncirCuError(ValueError):
    """Base class of every error the IncirCu core raises on bad input; its argument is a :class:`Message`."""

    @property
    def message(self):
        """The error's :class:`Message` (a plain ``str`` when it was raised with text)."""
        return self.args[0] if self.args else ""


class InvalidGeometryError(IncirCuError):
    """The geometry is empty, null, has NaN/inf coordinates or is not a valid polygon."""


class SplitPointError(IncirCuError):
    """The split points are missing, not two, identical, or too far from the polygon's boundary."""


class ChainError(IncirCuError):
    """A boundary chain is too short, crosses itself, or folds back over itself."""


class CrossingLinesError(IncirCuError):
    """In open mode the two lines cross or touch each other."""


class CenterlineError(IncirCuError):
    """The computed centerline would be unusable (it crosses itself), so none is returned."""


class OptionError(IncirCuError):
    """A numeric option (spacing, sample count, tolerance) is not a number, not finite, or out of range."""


def format_point(xy):
    """Return ``"(x, y)"`` with coordinates rounded for a message.

    Parameters
    ----------
    xy : sequence of float
        Coordinates, CRS units.

    Returns
    -------
    str
    """
    return f"({float(xy[0]):.10g}, {float(xy[1]):.10g})"
