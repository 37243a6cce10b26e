#pragma once
#include "meshtrace/util/math.h"

namespace meshtrace {

struct Material {
  Color ambient{0.0};
  Color diffuse{0.0};
  Color specular{0.0};
  double shininess = 0.0;
  double mirror = 0.0;  // reflectivity in [0, 1]
};

struct Light {
  Vec3 position{0.0};
  Color color{0.0};
};

}  // namespace meshtrace
