#include "mesh_store.hpp"

#include <charconv>

#include "pgamesh/io/read_mesh.hpp"

namespace pgamesh::viewer {

namespace {

// "f" + number; spelled this way because GCC 12 warns falsely (-Wrestrict) on literal + string.
std::string make_id(char kind, std::uint64_t number) {
  std::string id(1, kind);
  id += std::to_string(number);
  return id;
}

std::shared_ptr<const StoredMesh> parse(std::string id, const std::string& name,
                                        std::span<const char> bytes, double weld_tolerance) {
  auto stored = std::make_shared<StoredMesh>();
  stored->id = std::move(id);
  stored->name = name;
  stored->weld_tolerance = weld_tolerance;
  stored->mesh = read_mesh_bytes(bytes, name, &stored->source);
  return stored;
}

}  // namespace

std::string MeshStore::add_file(const std::string& path, const std::string& name,
                                const std::string& origin) {
  std::lock_guard lock(mutex_);
  File f;
  f.entry = {make_id('f', files_.size()), name, origin};
  f.path = path;
  files_.push_back(std::move(f));
  return files_.back().entry.id;
}

std::shared_ptr<const StoredMesh> MeshStore::add_upload(const std::string& name,
                                                        std::span<const char> bytes,
                                                        std::optional<double> weld_tolerance) {
  std::uint64_t number;
  {
    std::lock_guard lock(mutex_);
    number = next_upload_++;
  }
  // Parse outside the lock: other requests go on while a big upload is read.
  auto stored = parse(make_id('u', number), name, bytes, weld_tolerance.value_or(weld_tolerance_));
  std::lock_guard lock(mutex_);
  uploads_.emplace(number, stored);
  while (uploads_.size() > max_uploads_) uploads_.erase(uploads_.begin());
  return stored;
}

std::shared_ptr<const StoredMesh> MeshStore::add_mesh(const std::string& name, Mesh mesh,
                                                      MeshSource source, double weld_tolerance) {
  auto stored = std::make_shared<StoredMesh>();
  stored->name = name;
  stored->mesh = std::move(mesh);
  stored->source = std::move(source);
  stored->weld_tolerance = weld_tolerance;
  std::lock_guard lock(mutex_);
  const std::uint64_t number = next_upload_++;
  stored->id = make_id('u', number);
  uploads_.emplace(number, stored);
  while (uploads_.size() > max_uploads_) uploads_.erase(uploads_.begin());
  return stored;
}

std::shared_ptr<const StoredMesh> MeshStore::get(const std::string& id) {
  if (id.size() < 2) return nullptr;
  std::uint64_t number = 0;
  const char* first = id.data() + 1;
  const char* last = id.data() + id.size();
  const auto [end, ec] = std::from_chars(first, last, number);
  if (ec != std::errc() || end != last) return nullptr;

  std::lock_guard lock(mutex_);
  if (id[0] == 'u') {
    const auto it = uploads_.find(number);
    return it == uploads_.end() ? nullptr : it->second;
  }
  if (id[0] != 'f' || number >= files_.size()) return nullptr;
  File& f = files_[number];
  if (!f.loaded) {
    auto stored = std::make_shared<StoredMesh>();
    stored->id = f.entry.id;
    stored->name = f.entry.name;
    stored->weld_tolerance = weld_tolerance_;
    stored->mesh = read_mesh(f.path, &stored->source);
    f.loaded = std::move(stored);
  }
  return f.loaded;
}

std::vector<FileEntry> MeshStore::files() const {
  std::lock_guard lock(mutex_);
  std::vector<FileEntry> out;
  for (const File& f : files_) out.push_back(f.entry);
  return out;
}

}  // namespace pgamesh::viewer
