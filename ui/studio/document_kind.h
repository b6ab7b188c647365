// Which workspace a file belongs to: project XML names its content (<cam>, <vessel> or <fit>, bare or
// inside <polarform>); the scan formats of src/io (xyz, csv, txt, ply, stl, obj, off) go to the
// fit workspace. Used by File ▸ Open, drag-and-drop and --project.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "ui/studio/workspace_kind.h"

namespace polarform::studio {

// Throws InputError for XML that is malformed or holds no cam, vessel or fit, and for an
// extension that no workspace reads.
WorkspaceKind document_kind(const std::filesystem::path& file);

// The extensions File ▸ Open lists.
const std::vector<std::string>& openable_extensions();

}  // namespace polarform::studio
