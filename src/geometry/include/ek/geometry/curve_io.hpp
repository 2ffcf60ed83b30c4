#pragma once
/// \file
/// Reading and writing closed curves.
///
/// Formats (chosen by the file extension):
///  - .obj: "v x y z" vertex lines and optional "l i j ..." polyline lines
///    (1-based). With l lines the vertex order is the order of the cycle they
///    form, starting at vertex 1; an open chain is closed by joining its ends.
///    Other OBJ statements (#, o, g, s, vn, vt) are ignored.
///  - .txt: one vertex "x y z" per line; blank lines and lines starting with
///    '#' are ignored.
/// In both formats the last vertex is joined to the first. A last vertex that
/// repeats the first exactly (an explicit closing vertex) is dropped.
///
/// Reading validates the curve (validate_closed_curve); every problem is an
/// InputError whose message names the file and, where it applies, the line.
#include <string>

#include "ek/geometry/types.hpp"

namespace ek {

/// Reads a closed curve (.obj or .txt). Throws InputError on any problem.
Points read_curve(const std::string& path);

/// Reads the rows of a curve file as vectors, one per vertex line in file
/// order (.obj `v` lines, `l` lines ignored; .txt lines), without a curve's
/// checks: no closing vertex dropped, equal rows allowed (velocities, for
/// example). Throws InputError for a malformed or non-finite line or no row.
Points read_vectors(const std::string& path);

/// Writes a closed curve (.obj or .txt, by extension) atomically: the file is
/// replaced only when completely written. Coordinates are written with 17
/// significant digits, so reading gives the same doubles back.
void write_curve(const std::string& path, const Points& P);

/// Parses curve text in the given format ("obj" or "txt"); `source` names the
/// input in error messages.
Points parse_curve(const std::string& text, const std::string& format, const std::string& source);

/// Checks that P is a usable closed polygon: at least 4 vertices, finite
/// coordinates, no zero-length edge (consecutive vertices closer than
/// 1e-12 times the bounding-box diagonal). Throws InputError naming `source`.
void validate_closed_curve(const Points& P, const std::string& source);

}  // namespace ek
