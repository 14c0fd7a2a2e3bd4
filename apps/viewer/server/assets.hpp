// The page's own files, served from memory. A fixed table maps each URL to one file under the web
// folder; every file is read once at start-up. No filesystem path is ever built from a request, so
// nothing outside the table can be served (docs/viewer.md, Limits and safety: a server serves only
// its own assets).
#pragma once

#include <map>
#include <string>
#include <vector>

namespace pgamesh::viewer {

struct Asset {
  std::string content_type;
  std::string body;
};

struct AssetTable {
  std::map<std::string, Asset> by_url;  // "/app.js" -> its bytes
  std::vector<std::string> missing;     // files of the table that could not be read
};

/// Reads every file of the page's fixed table from web_dir (the folder holding index.html; the
/// three.js files come from web_dir/node_modules, installed by scripts/setup.sh). Files that cannot
/// be read are listed in `missing` and are not served.
AssetTable load_assets(const std::string& web_dir);

}  // namespace pgamesh::viewer
