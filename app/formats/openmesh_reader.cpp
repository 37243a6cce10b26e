#include "formats/openmesh_reader.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <algorithm>
#include <cctype>
#include <iostream>
#include <mutex>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "formats/file_checks.h"
#include "meshtrace/geometry/polygon.h"
#include "meshtrace/io/input_error.h"
#include "meshtrace/io/load_observer.h"
#include "meshtrace/io/mesh_reader.h"
#include "meshtrace/io/ply_reader.h"

namespace meshtrace::formats {

namespace {
struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
};
// Holds the points and, per face, a handle for the readers' face attributes.
using PointMesh = OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits>;

// What the importer keeps per vertex (the point and OpenMesh's outgoing
// halfedge handle, then the copy in MeshData) and per face (a halfedge
// handle): planned in the budget before the arrays grow.
constexpr std::uint64_t kBytesPerVertex = sizeof(OpenMesh::Vec3d) + 4 + sizeof(Vec3);
constexpr std::uint64_t kBytesPerFace = 4;
constexpr std::size_t kFirstBlock = 4096;

// A read's progress for the load observer, in bytes of the file: OpenMesh's
// readers do not say how far into the file they are, so the share read is
// taken as the share of the elements (vertices, then faces, as the check
// before the read counted them) the importer has been given.
class ReadProgress {
 public:
  ReadProgress(LoadObserver* observer, std::filesystem::path file, std::uint64_t fileBytes,
               formats::ElementCounts counts)
      : observer_(observer), file_(std::move(file)), fileBytes_(fileBytes), counts_(counts) {}

  void vertex() {
    if (counts_.vertices > 0) step();
  }
  void face() { step(); }
  // The rest of the file, once the read is over.
  void finish() { report(fileBytes_); }

 private:
  // A report every 64k elements: a few MB of text, as the other readers
  // report a piece of the file at a time.
  static constexpr std::uint64_t kElementsAPiece = 1 << 16;

  void step() {
    if (++done_ % kElementsAPiece != 0) return;
    const std::uint64_t total = counts_.vertices + counts_.faces;
    if (total == 0) return;  // more elements than the check counted: none
    const auto share = static_cast<double>(std::min(done_, total)) / static_cast<double>(total);
    report(static_cast<std::uint64_t>(share * static_cast<double>(fileBytes_)));
  }
  void report(std::uint64_t bytes) {
    if (!observer_ || bytes <= reported_) return;
    observer_->bytesRead(file_, bytes - reported_, fileBytes_);
    reported_ = bytes;
  }

  LoadObserver* observer_;
  std::filesystem::path file_;
  std::uint64_t fileBytes_;
  formats::ElementCounts counts_;
  std::uint64_t done_ = 0, reported_ = 0;
};

// Takes each face's corners as OFF's reader does (appendPolygonTriangles) instead
// of building OpenMesh's halfedge topology, which drops or splits the
// faces a non-manifold mesh has. Ignores the readers' reserve calls: they
// pass counts from the file's header, unchecked.
class CornerImporter : public OpenMesh::IO::ImporterT<PointMesh> {
 public:
  CornerImporter(PointMesh& mesh, MeshData& out, MemoryBudget& budget, std::string name,
                 ReadProgress& progress)
      : ImporterT(mesh),
        mesh_(mesh),
        out_(out),
        budget_(budget),
        name_(std::move(name)),
        progress_(progress) {}

  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3f& p) override {
    return add_vertex(OpenMesh::Vec3d(p));
  }
  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3d& p) override {
    planVertex();
    return ImporterT::add_vertex(p);
  }
  OpenMesh::VertexHandle add_vertex() override {
    planVertex();
    return ImporterT::add_vertex();
  }

  OpenMesh::FaceHandle add_face(const VHandles& corners) override {
    const std::size_t face = faces_++;
    if (!problem_.empty()) return OpenMesh::FaceHandle();
    if (corners.size() < 3) {
      problem_ = "face " + std::to_string(face) + " has " + std::to_string(corners.size()) +
                 " corners; at least 3 are needed";
      return OpenMesh::FaceHandle();
    }
    for (const OpenMesh::VertexHandle& c : corners) {
      if (!c.is_valid() || static_cast<std::size_t>(c.idx()) >= mesh_.n_vertices()) {
        problem_ = "face " + std::to_string(face) + " refers to vertex " + std::to_string(c.idx()) +
                   " of " + std::to_string(mesh_.n_vertices());
        return OpenMesh::FaceHandle();
      }
    }
    planTriangles(corners.size() - 2);
    progress_.face();
    indices_.clear();
    for (const OpenMesh::VertexHandle& c : corners)
      indices_.push_back(static_cast<std::uint32_t>(c.idx()));
    appendPolygonTriangles(indices_, out_.triangles, &out_.polygons);
    return mesh_.new_face();
  }

  // Texture coordinates walk a face's halfedges, which these faces lack.
  void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle,
                          const std::vector<OpenMesh::Vec2f>&) override {}
  void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle,
                          const std::vector<OpenMesh::Vec3f>&) override {}
  void reserve(unsigned int, unsigned int, unsigned int) override {}

  // The first face found wrong, or "".
  const std::string& problem() const { return problem_; }

 private:
  void planVertex() {
    progress_.vertex();
    if (mesh_.n_vertices() < plannedVertices_) return;
    const std::size_t more = std::max(kFirstBlock, plannedVertices_);
    budget_.reserve(more * kBytesPerVertex, "load",
                    "the " + std::to_string(plannedVertices_ + more) + " vertices of " + name_);
    plannedVertices_ += more;
    mesh_.reserve(plannedVertices_, 0, plannedFaces_);
  }
  void planTriangles(std::size_t count) {
    if (out_.triangles.size() + count <= out_.triangles.capacity() &&
        mesh_.n_faces() < plannedFaces_)
      return;
    const std::size_t more = std::max({kFirstBlock, out_.triangles.capacity(), count});
    // The old and the new triangle array while it grows, and the faces.
    budget_.reserve(
        (out_.triangles.capacity() + more) * sizeof(TriangleIndices) + more * kBytesPerFace, "load",
        "the " + std::to_string(out_.triangles.size() + more) + " triangles of " + name_);
    budget_.release(out_.triangles.capacity() * sizeof(TriangleIndices));
    out_.triangles.reserve(out_.triangles.capacity() + more);
    plannedFaces_ += more;
    mesh_.reserve(plannedVertices_, 0, plannedFaces_);
  }

  PointMesh& mesh_;
  MeshData& out_;
  MemoryBudget& budget_;
  std::string name_;
  std::size_t plannedVertices_ = 0;
  std::size_t plannedFaces_ = 0;
  std::size_t faces_ = 0;
  std::vector<std::uint32_t> indices_;  // of the face being added
  std::string problem_;
  ReadProgress& progress_;
};

// OM files store the halfedge structure: their faces come with halfedges
// rather than corner lists. Walks each face's loop (checking every handle
// against the arrays, and stopping after as many steps as there are
// halfedges) into triangles; returns what is wrong, or "".
std::string collectHalfedgeFaces(const PointMesh& mesh, MeshData& out) {
  const auto halfedges = static_cast<int>(mesh.n_halfedges());
  const auto vertices = static_cast<int>(mesh.n_vertices());
  std::vector<std::uint32_t> corners;
  for (int f = 0; f < static_cast<int>(mesh.n_faces()); ++f) {
    const std::string face = "face " + std::to_string(f);
    const auto first = mesh.halfedge_handle(OpenMesh::FaceHandle(f));
    if (!(first.idx() >= 0 && first.idx() < halfedges)) return face + " has no halfedge";
    corners.clear();
    auto h = first;
    do {
      const auto v = mesh.to_vertex_handle(h);
      if (!(v.idx() >= 0 && v.idx() < vertices))
        return face + " refers to vertex " + std::to_string(v.idx()) + " of " +
               std::to_string(vertices);
      corners.push_back(static_cast<std::uint32_t>(v.idx()));
      h = mesh.next_halfedge_handle(h);
      if (!(h.idx() >= 0 && h.idx() < halfedges)) return face + ": its halfedge loop is broken";
      if (corners.size() > static_cast<std::size_t>(halfedges))
        return face + ": its halfedge loop does not close";
    } while (h != first);
    if (corners.size() < 3)
      return face + " has " + std::to_string(corners.size()) + " corners; at least 3 are needed";
    appendPolygonTriangles(corners, out.triangles, &out.polygons);
  }
  return "";
}

// Meshes beyond this are refused, as OFF's are.
constexpr std::uintmax_t kMaxMeshBytes = std::uintmax_t{4} << 30;

// The file mapped read-only for its check: nothing is allocated for it.
class MappedFile {
 public:
  explicit MappedFile(const std::filesystem::path& file) {
    fd_ = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd_ < 0) throw InputError::inFile(file, "cannot open the mesh file");
    struct stat info {};
    if (::fstat(fd_, &info) != 0 || !S_ISREG(info.st_mode))
      throw InputError::inFile(file, "not a regular file");
    size_ = static_cast<std::size_t>(info.st_size);
    if (size_ == 0) throw InputError::inFile(file, "empty file");
    if (size_ > kMaxMeshBytes)
      throw InputError::inFile(file, "larger than the " + formatBytes(kMaxMeshBytes) + " accepted");
    data_ = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, fd_, 0);
    if (data_ == MAP_FAILED) throw InputError::inFile(file, "cannot map the mesh file");
  }
  ~MappedFile() {
    if (data_ != MAP_FAILED) ::munmap(data_, size_);
    if (fd_ >= 0) ::close(fd_);
  }
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  std::string_view bytes() const { return {static_cast<const char*>(data_), size_}; }

 private:
  int fd_ = -1;
  void* data_ = MAP_FAILED;
  std::size_t size_ = 0;
};

// What OpenMesh's reader of `file`'s extension must not be handed; returns
// the file's size and what it holds.
std::pair<std::uint64_t, formats::ElementCounts> checkBeforeReading(
    const std::filesystem::path& file) {
  const MappedFile mapped(file);
  std::string extension = file.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  formats::ElementCounts counts;
  if (extension == ".ply") counts = checkPly(file, mapped.bytes());
  if (extension == ".om") checkOm(file, mapped.bytes());
  return {mapped.bytes().size(), counts};
}

// OpenMesh's readers keep the state of a read in their (global) instances
// and report through its global streams: one read at a time.
std::mutex& readLock() {
  static std::mutex lock;
  return lock;
}

// OpenMesh's PLY reader reports a value type it cannot convert (an integer
// coordinate, say) straight to std::cerr, past its own streams, sets the
// value to 0 and reads on from the wrong place, so the rest of the file is
// misread. What it writes there during a read is caught, and the read
// refused with it. (Our own code writes to stderr through stdio, never
// std::cerr, and the read holds readLock.)
class CerrCatcher {
 public:
  CerrCatcher() : previous_(std::cerr.rdbuf(caught_.rdbuf())) {}
  ~CerrCatcher() { std::cerr.rdbuf(previous_); }
  CerrCatcher(const CerrCatcher&) = delete;
  CerrCatcher& operator=(const CerrCatcher&) = delete;

  // The first line written, or "".
  std::string firstLine() const {
    const std::string text = caught_.str();
    return text.substr(0, text.find('\n'));
  }

 private:
  std::ostringstream caught_;
  std::streambuf* previous_;
};

// OpenMesh's readers print to its global streams; the checks before them
// say what is wrong instead. (Capturing the streams is no option: their
// disconnect() leaks the target it removes.)
void silenceOpenMesh() {
  ::omerr().disable();
  ::omlog().disable();
  ::omout().disable();
}
}  // namespace

void registerOpenMeshFormats() {
  static std::once_flag once;
  std::call_once(once, [] {
    registerMeshReader(".om", readOpenMeshFile);
    // PLY is read by the core's reader, streamed (quicker than OpenMesh's
    // generic properties, and in double from ASCII); the rare layouts it
    // leaves come here.
    registerMeshReader(".ply", [](const std::filesystem::path& file, MemoryBudget& budget) {
      if (std::optional<MeshData> mesh = readPly(file, budget)) return std::move(*mesh);
      return readOpenMeshFile(file, budget);
    });
  });
}

MeshData readOpenMeshFile(const std::filesystem::path& file, MemoryBudget& budget) {
  const auto [fileBytes, counts] = checkBeforeReading(file);
  ReadProgress progress(budget.loadObserver(), file, fileBytes, counts);
  MeshData out;
  PointMesh mesh;
  std::string problem;
  bool read = false;
  {
    const std::lock_guard<std::mutex> hold(readLock());
    silenceOpenMesh();
    CornerImporter importer(mesh, out, budget, file.filename().string(), progress);
    OpenMesh::IO::Options options;
    const CerrCatcher complaints;
    read = OpenMesh::IO::IOManager().read(file.string(), importer, options);
    problem = importer.problem();
    // The cause comes first: what the importer then found wrong follows
    // from the misread.
    if (const std::string said = complaints.firstLine(); !said.empty())
      problem = "OpenMesh's reader cannot read its values (it says \"" + said + "\")";
    if (read && problem.empty()) progress.finish();
  }
  if (read && problem.empty() && out.triangles.empty() && mesh.n_faces() > 0) {
    // A face's loop has at most n_halfedges corners: the triangles are fewer.
    budget.reserve(mesh.n_halfedges() * sizeof(TriangleIndices), "load",
                   "the triangles of the " + std::to_string(mesh.n_faces()) + " faces of " +
                       file.filename().string());
    problem = collectHalfedgeFaces(mesh, out);
  }
  if (!problem.empty()) throw InputError::inFile(file, problem);
  if (!read) {
    throw InputError::inFile(file, "OpenMesh's reader cannot read this file");
  }
  out.vertices.reserve(mesh.n_vertices());
  for (const PointMesh::VertexHandle v : mesh.vertices()) {
    const OpenMesh::Vec3d& p = mesh.point(v);
    out.vertices.emplace_back(p[0], p[1], p[2]);
  }
  // OpenMesh's copy of the points goes with `mesh`.
  budget.release(mesh.n_vertices() * (kBytesPerVertex - sizeof(Vec3)));
  finishPolygons(out, budget, file);
  return out;
}

}  // namespace meshtrace::formats
