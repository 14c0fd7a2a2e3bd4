#include "assets.hpp"

#include <cstdio>
#include <memory>

namespace pgamesh::viewer {

namespace {

struct AssetFile {
  const char* url;
  const char* file;  // relative to the web folder
  const char* content_type;
};

// The whole list of what the server may send besides the API. three.js is used as an ES module
// through the import map in index.html ("three" -> /vendor/three/three.module.js).
constexpr AssetFile kAssets[] = {
    {"/", "index.html", "text/html; charset=utf-8"},
    {"/index.html", "index.html", "text/html; charset=utf-8"},
    {"/style.css", "style.css", "text/css; charset=utf-8"},
    {"/app.js", "app.js", "application/javascript; charset=utf-8"},
    {"/api.js", "api.js", "application/javascript; charset=utf-8"},
    {"/scene.js", "scene.js", "application/javascript; charset=utf-8"},
    {"/panels.js", "panels.js", "application/javascript; charset=utf-8"},
    {"/props_panel.js", "props_panel.js", "application/javascript; charset=utf-8"},
    {"/fuel_panel.js", "fuel_panel.js", "application/javascript; charset=utf-8"},
    {"/gauge_plot.js", "gauge_plot.js", "application/javascript; charset=utf-8"},
    {"/vendor/three/three.module.js", "node_modules/three/build/three.module.js",
     "application/javascript; charset=utf-8"},
    {"/vendor/three/three.core.js", "node_modules/three/build/three.core.js",
     "application/javascript; charset=utf-8"},
    {"/vendor/three/OrbitControls.js", "node_modules/three/examples/jsm/controls/OrbitControls.js",
     "application/javascript; charset=utf-8"},
};

bool read_whole_file(const std::string& path, std::string& out) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), std::fclose);
  if (!f) return false;
  out.clear();
  char buffer[1 << 16];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, f.get())) > 0) out.append(buffer, n);
  return !std::ferror(f.get());
}

}  // namespace

AssetTable load_assets(const std::string& web_dir) {
  AssetTable table;
  for (const AssetFile& a : kAssets) {
    Asset asset{a.content_type, {}};
    if (read_whole_file(web_dir + "/" + a.file, asset.body))
      table.by_url.emplace(a.url, std::move(asset));
    else
      table.missing.push_back(web_dir + "/" + a.file);
  }
  return table;
}

}  // namespace pgamesh::viewer
