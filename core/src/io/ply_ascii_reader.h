#pragma once
// ASCII PLY, read as OFF's text is read: in double, whatever type the
// header declares, so that the same numbers give the same mesh in either
// format, and in parallel pieces (text::readElementLines).
#include "io/file_source.h"
#include "meshtrace/geometry/mesh.h"
#include "meshtrace/io/memory_budget.h"

namespace meshtrace {

// Reads `source`, an ASCII PLY file of a readablePlyLayout, one record to a
// line as the format has them (blank lines are skipped). Every value is
// checked against its declared kind (a number, or an integer for integer
// types); coordinates are read as the text states them. Throws InputError
// naming the file, the line and the element ("vertex 12") for a bad
// record: a value of the wrong kind, too few or too many values, a bad
// list count, a face's corner count or index out of range, a non-finite
// coordinate; and for a file that ends before its elements do.
MeshData readAsciiPly(text::FileSource& source, MemoryBudget& budget);

}  // namespace meshtrace
