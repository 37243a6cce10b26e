#pragma once
// What a query looks for: the closest hit along a ray, or any hit below a
// limit (a shadow ray's blocker). The traversals and the queries are written
// once and take it as a template parameter.

namespace meshtrace {

enum class HitKind { Closest, Any };

}  // namespace meshtrace
