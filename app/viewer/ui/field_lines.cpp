#include <imgui.h>

#include "viewer/model/line_breaks.h"
#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

void textFields(const std::vector<std::string>& fields, const std::string& separator) {
  for (const std::string& line :
       breakBetweenFields(fields, separator, ImGui::GetContentRegionAvail().x,
                          [](const std::string& s) { return ImGui::CalcTextSize(s.c_str()).x; }))
    ImGui::TextUnformatted(line.c_str());
}

}  // namespace meshtrace::viewer
