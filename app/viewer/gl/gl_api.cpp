#include "viewer/gl/gl_api.h"

#define MESHTRACE_GL_DEFINE(type, name) type meshtrace_##name = nullptr;
MESHTRACE_GL_FUNCTIONS(MESHTRACE_GL_DEFINE)
#undef MESHTRACE_GL_DEFINE

namespace meshtrace::gl {

const char* loadFunctions(ProcLoader load) {
  const char* missing = nullptr;
#define MESHTRACE_GL_LOAD(type, name)                     \
  meshtrace_##name = reinterpret_cast<type>(load(#name)); \
  if (!meshtrace_##name && !missing) missing = #name;
  MESHTRACE_GL_FUNCTIONS(MESHTRACE_GL_LOAD)
#undef MESHTRACE_GL_LOAD
  return missing;
}

}  // namespace meshtrace::gl
