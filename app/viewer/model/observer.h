#pragma once
// The observer: a second, free camera that looks at the scene from outside
// the main camera, to see where the main camera's rays go. It starts back
// and up from the main camera, turned so that the main camera's eye and
// what it looks at are both in view, and is moved with the mouse like the
// main one.
#include <utility>
#include <vector>

#include "meshtrace/geometry/scene.h"

namespace meshtrace::viewer {

// A view of `main`'s eye and of `scene`'s objects, from above and aside;
// the image size is the main camera's.
CameraSpec observerCamera(const CameraSpec& main, const Scene& scene);

// The main camera's frustum as segments: from the eye to the image's four
// corners on a plane at `reach` along the view (at least the centre's
// distance), and that image's outline.
std::vector<std::pair<Vec3, Vec3>> frustumLines(const CameraSpec& main, double reach);

// The bounds of everything bounded in the scene (meshes, spheres,
// cylinders), or an empty box.
Aabb sceneBounds(const Scene& scene);

}  // namespace meshtrace::viewer
