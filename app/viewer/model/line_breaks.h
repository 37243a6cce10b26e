#pragma once
// Breaking a line of text to a width at its spaces only: never inside a
// number, as ImGui's own wrapping does after a '.' or ',' ("5." then
// "50000" reads as two numbers).
#include <functional>
#include <string>
#include <vector>

namespace meshtrace::viewer {

// The pieces of `text` that fit `firstWidth` (the first) and `width` (the
// others) as `measure` gives a string's width, each without the spaces it
// was broken at; a word wider than its line stands alone. A text that fits
// is one piece; an empty one, one empty piece.
std::vector<std::string> breakAtSpaces(const std::string& text, float firstWidth, float width,
                                       const std::function<float(const std::string&)>& measure);

}  // namespace meshtrace::viewer
