#pragma once
// The files a RenderSettings names (its string fields: the bump, displacement
// and environment maps, a volume, the emitters' sprites), as written in it.
// What an image depends on beyond the scene file and the values themselves:
// `facet batch --resume` hashes their bytes.
#include <functional>
#include <string>
#include <vector>

#include "settings/render_settings.h"

namespace facet {

// Every non-empty file name in `settings`, in field-table order.
std::vector<std::string> namedFiles(const RenderSettings& settings);

// Calls visit(name) on each non-empty file name in `settings`, in
// field-table order; visit may change the name (a job file's folder put in
// front of a relative one).
void forEachNamedFile(RenderSettings& settings, const std::function<void(std::string&)>& visit);

}  // namespace facet
