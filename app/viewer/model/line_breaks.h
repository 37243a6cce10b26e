#pragma once
// Fitting text to a width: a line broken at its spaces only, never inside
// a number, as ImGui's own wrapping does after a '.' or ',' ("5." then
// "50000" reads as two numbers); a line of fields (the Render panel's timings)
// broken between fields only; a name cut short with "...".
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

// The lines of `fields` joined by `separator`, each as many whole fields as
// fit `width`; a field wider than a line stands alone. All on one line when
// they fit.
std::vector<std::string> breakBetweenFields(
    const std::vector<std::string>& fields, const std::string& separator, float width,
    const std::function<float(const std::string&)>& measure);

// `text` if it fits `width`, else its longest beginning that fits with
// "..." after it (at least its first character, to tell names apart).
std::string elide(const std::string& text, float width,
                  const std::function<float(const std::string&)>& measure);

}  // namespace meshtrace::viewer
