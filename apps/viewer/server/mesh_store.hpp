// The meshes a running server knows: files named on the command line and the bundled ones (read on
// first use), and uploads (parsed at once, the oldest evicted beyond a fixed count so memory stays
// bounded). Entries are immutable once stored and shared with the request threads.
#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "pgamesh/core/mesh.hpp"

namespace pgamesh::viewer {

struct FuelModel;  // fuel_model.hpp

struct StoredMesh {
  std::string id;    // "f0", "f1", ... for files, "u1", "u2", ... for uploads
  std::string name;  // what the page shows: the file name or the uploaded file's name
  Mesh mesh;         // as read; the analyses weld it within weld_tolerance
  MeshSource source;
  double weld_tolerance = 0;  // `--weld-tolerance` of pgamesh serve, or the upload's own
  // Built on first use by fuel_model(), under cache_mutex.
  mutable std::mutex cache_mutex;
  mutable std::shared_ptr<const FuelModel> fuel;
};

struct FileEntry {
  std::string id;
  std::string name;
  std::string origin;  // "bundled" or "command line"
};

class MeshStore {
 public:
  /// A store keeping at most `max_uploads` uploaded meshes (the oldest is dropped first); the
  /// meshes are analysed welded within `weld_tolerance` unless an upload names its own.
  explicit MeshStore(std::size_t max_uploads, double weld_tolerance = 0)
      : max_uploads_(max_uploads), weld_tolerance_(weld_tolerance) {}

  /// Registers a mesh file to be read when first asked for; returns its id.
  std::string add_file(const std::string& path, const std::string& name, const std::string& origin);

  /// Parses uploaded bytes (format detected from the content) and stores the mesh. Throws
  /// pgamesh::InputError naming `name` and the position when the bytes are not a readable mesh.
  std::shared_ptr<const StoredMesh> add_upload(const std::string& name, std::span<const char> bytes,
                                               std::optional<double> weld_tolerance = {});

  /// Stores a mesh made here (the Repair action's result) as an upload; returns it.
  std::shared_ptr<const StoredMesh> add_mesh(const std::string& name, Mesh mesh, MeshSource source,
                                             double weld_tolerance);

  /// The mesh with this id, or nullptr when no such id is known (or the upload was evicted).
  /// Reads a registered file on first use; throws pgamesh::InputError when it is not readable.
  std::shared_ptr<const StoredMesh> get(const std::string& id);

  /// The registered files, in the order they were added.
  std::vector<FileEntry> files() const;

 private:
  struct File {
    FileEntry entry;
    std::string path;
    std::shared_ptr<const StoredMesh> loaded;
  };
  mutable std::mutex mutex_;
  std::size_t max_uploads_;
  double weld_tolerance_ = 0;
  std::vector<File> files_;
  std::map<std::uint64_t, std::shared_ptr<const StoredMesh>> uploads_;  // by upload number
  std::uint64_t next_upload_ = 1;
};

}  // namespace pgamesh::viewer
