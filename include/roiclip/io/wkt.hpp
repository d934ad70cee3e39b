// SPDX-License-Identifier: MIT
// roiclip::io WKT: reading and writing regions and open polylines as OGC Well-Known Text, through
// Boost.Geometry's read_wkt() and wkt().
//
// Coordinates are taken as they are (x = first number, y = second), in roiclip's y-down pixel
// convention. A third (z) or fourth (m) value per point, tagged (POLYGON Z ((...))) or not, is
// dropped: one Warning per input in ReadOptions::warnings.
#pragma once

#include <string>
#include <vector>

#include <roiclip/io/feature.hpp>

namespace roiclip::io {

/// Read regions from WKT text: a POLYGON, a MULTIPOLYGON, or a GEOMETRYCOLLECTION of them
/// (collections may nest). A POLYGON or MULTIPOLYGON gives one Feature; a top-level
/// GEOMETRYCOLLECTION gives one Feature per member (what featuresToWkt() writes for several
/// features), a nested one adds its polygons to its member's Feature. EMPTY geometries give
/// features without polygons. Features have no id and no properties (WKT has none). Rings are
/// checked and closing points dropped as in parsePaths(). Blank space, including line breaks, is
/// free.
/// @param source name of the input used in error messages.
/// @throws InvalidInputError (message starts with `source`) on text Boost.Geometry cannot read,
///         other geometry types, more than 4 values in a point, a coordinate that is not finite,
///         or a ring with fewer than 3 distinct points (unless options allow it); the message
///         names the ring ("member 1, polygon 0, ring 2 (path 5)").
std::vector<Feature> parseWktFeatures(const std::string& text,
                                      const std::string& source = "<string>",
                                      const ReadOptions& options = {});

/// Read open polylines from WKT text: a LINESTRING, a MULTILINESTRING or a GEOMETRYCOLLECTION of
/// them; points kept as parseLines() keeps them. @throws InvalidInputError as parseWktFeatures().
Paths parseWktLines(const std::string& text, const std::string& source = "<string>",
                    const ReadOptions& options = {});

/// Features as WKT, one line: a MULTIPOLYGON for one feature (MULTIPOLYGON EMPTY when it has no
/// polygon), a GEOMETRYCOLLECTION of one MULTIPOLYGON per feature for several (GEOMETRYCOLLECTION
/// EMPTY for none). Rings closed by repeating their first point, ordered as `orientation` asks;
/// ids and properties cannot be written. Coordinates with 17 significant digits (exact doubles).
std::string featuresToWkt(const std::vector<Feature>& features,
                          RingOrientation orientation = RingOrientation::Rfc7946);

/// Polylines as one WKT MULTILINESTRING (MULTILINESTRING EMPTY for none), points as they are.
std::string linesToWkt(const Paths& lines);

}  // namespace roiclip::io
