#include "ui/studio/document_kind.h"

#include <algorithm>
#include <cctype>
#include <cstring>

#include "jobs/project/xml_reader.h"
#include "src/error.h"

namespace polarform::studio {
namespace {

const std::vector<std::string> kCloudExtensions = {".xyz", ".csv", ".txt", ".pts",
                                                   ".ply", ".stl", ".obj", ".off"};

}  // namespace

const std::vector<std::string>& openable_extensions() {
  static const std::vector<std::string> all = [] {
    std::vector<std::string> e = {".xml"};
    e.insert(e.end(), kCloudExtensions.begin(), kCloudExtensions.end());
    return e;
  }();
  return all;
}

WorkspaceKind document_kind(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (std::find(kCloudExtensions.begin(), kCloudExtensions.end(), ext) != kCloudExtensions.end())
    return WorkspaceKind::fit;
  if (ext != ".xml")
    throw InputError(
        file.string() + ": unknown file type '" + ext +
        "'; expected a project (.xml) or a point cloud (.xyz, .csv, .ply, .stl, .obj, .off)");
  const XmlDocument doc(file);
  const tinyxml2::XMLElement* root = doc.root();
  if (!root) throw InputError(file.string() + ": empty XML document");
  const auto names = [](const tinyxml2::XMLElement* e, const char* name) {
    return std::strcmp(e->Name(), name) == 0;
  };
  if (names(root, "cam") || (names(root, "polarform") && root->FirstChildElement("cam")))
    return WorkspaceKind::cam;
  if (names(root, "vessel") || (names(root, "polarform") && root->FirstChildElement("vessel")))
    return WorkspaceKind::vessel;
  if (names(root, "fit") || (names(root, "polarform") && root->FirstChildElement("fit")))
    return WorkspaceKind::fit;
  throw InputError(file.string() +
                   ": neither a cam, a vessel nor a fit project (expected a <cam>, <vessel> or "
                   "<fit> element)");
}

}  // namespace polarform::studio
