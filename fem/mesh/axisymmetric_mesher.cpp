#include "fem/mesh/axisymmetric_mesher.hpp"

#include <gmsh.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <locale>
#include <random>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace pilempm::fem {
namespace {

constexpr int kGmshQuad4 = 3;  // gmsh element type of the 4-node quadrangle

// Same threshold as the .geo uses, so both agree on which intervals have zero height.
double zero_height_tolerance(const PileGeometry& g) {
    return 1e-12 * (std::abs(g.stations.back().z - g.stations.front().z) + 1.0);
}

void validate(const PileGeometry& g, double element_size, int radial_divisions) {
    if (!(element_size > 0.0) || !std::isfinite(element_size))
        throw std::invalid_argument("axisymmetric mesher: element_size must be > 0");
    if (radial_divisions < 1)
        throw std::invalid_argument("axisymmetric mesher: radial_divisions must be >= 1");
    const auto& s = g.stations;
    if (s.size() < 2 || !(g.length() > 0.0))
        throw std::invalid_argument("axisymmetric mesher: geometry needs stations over L > 0");
    if (std::abs(s.front().z) > 1e-9 * g.length())
        throw std::invalid_argument(
            "axisymmetric mesher: the first station must be the toe, z = 0");
    const double tol = zero_height_tolerance(g);
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (!(s[i].inner_radius >= 0.0 && s[i].outer_radius > s[i].inner_radius))
            throw std::invalid_argument("axisymmetric mesher: station needs 0 <= ri < ro");
        if (i == 0) continue;
        const double dz = s[i].z - s[i - 1].z;
        if (dz < -tol)
            throw std::invalid_argument("axisymmetric mesher: stations must be ordered by z");
        // Two different walls at one z would give a non-conforming (disconnected) mesh.
        const bool same_wall = s[i].inner_radius == s[i - 1].inner_radius &&
                               s[i].outer_radius == s[i - 1].outer_radius;
        if (dz <= tol && !same_wall) {
            std::ostringstream msg;
            msg << "axisymmetric mesher: radius step at z = " << s[i].z
                << " m cannot be meshed conformingly; use a taper (taper_ratio > 0)";
            throw std::invalid_argument(msg.str());
        }
    }
}

// Axial divisions of each interval between consecutive stations (1 for zero height,
// which the .geo skips anyway).
std::vector<int> axial_divisions(const PileGeometry& g, double element_size) {
    std::vector<int> nz;
    for (std::size_t i = 1; i < g.stations.size(); ++i) {
        const double height = g.stations[i].z - g.stations[i - 1].z;
        nz.push_back(std::max(1, static_cast<int>(std::lround(height / element_size))));
    }
    return nz;
}

// The generated .geo that defines the parameters of the mesh script. 17 significant
// digits round-trip a double, so the mesh corners are exactly the stations.
std::string parameter_script(const PileGeometry& g, const std::vector<int>& nz, int nr) {
    std::ostringstream out;
    out.imbue(std::locale::classic());  // '.' decimal point whatever the global locale
    out.precision(17);
    auto list = [&out](const char* name, const auto& values, auto field) {
        out << name << "[] = {";
        for (std::size_t i = 0; i < values.size(); ++i) out << (i ? ", " : "") << field(values[i]);
        out << "};\n";
    };
    list("st_z", g.stations, [](const PileStation& s) { return s.z; });
    list("st_ri", g.stations, [](const PileStation& s) { return s.inner_radius; });
    list("st_ro", g.stations, [](const PileStation& s) { return s.outer_radius; });
    list("nz", nz, [](int n) { return n; });
    out << "nr = " << nr << ";\n";
    return out.str();
}

// A uniquely named file in the temp directory, removed when the object goes out of scope.
class TemporaryFile {
   public:
    explicit TemporaryFile(const std::string& contents) {
        std::random_device entropy;
        for (int attempt = 0; attempt < 16 && path_.empty(); ++attempt) {
            const auto name = "pilempm_wall_" + std::to_string(entropy()) + ".geo";
            const auto candidate = std::filesystem::temp_directory_path() / name;
            // "x": fail rather than overwrite a file another process just created.
            if (std::FILE* f = std::fopen(candidate.c_str(), "wx")) {
                const bool ok =
                    std::fwrite(contents.data(), 1, contents.size(), f) == contents.size();
                if (std::fclose(f) == 0 && ok)
                    path_ = candidate.string();
                else
                    std::filesystem::remove(candidate);
            }
        }
        if (path_.empty())
            throw std::runtime_error("cannot write the gmsh parameter file in the temp directory");
    }
    ~TemporaryFile() {
        std::error_code ignored;
        std::filesystem::remove(path_, ignored);
    }
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;
    const std::string& path() const { return path_; }

   private:
    std::string path_;
};

// One gmsh API session, finalised on every exit path. Errors are logged rather than
// thrown: an exception thrown from inside the .geo parser leaves gmsh's lexer broken for
// every later parse in the process.
// gmsh sets OpenMP's thread count for the whole process to its General.NumThreads (1):
// the count the process had is put back, or every later MPM step runs on one thread.
class GmshSession {
   public:
    GmshSession() : threads_(omp_get_max_threads()) {
        gmsh::initialize(0, nullptr, false);  // no user gmshrc: the result must not depend on it
        gmsh::option::setNumber("General.Terminal", 0);
        gmsh::option::setNumber("General.AbortOnError", 0);
        gmsh::logger::start();
    }
    ~GmshSession() {
        try {
            gmsh::logger::stop();
            gmsh::finalize();
        } catch (...) {
        }
        omp_set_num_threads(threads_);
    }
    GmshSession(const GmshSession&) = delete;
    GmshSession& operator=(const GmshSession&) = delete;

    // Throws with the logged error messages, if gmsh reported any.
    void throw_if_errors() const {
        std::vector<std::string> log;
        gmsh::logger::get(log);
        std::string errors;
        for (const auto& line : log) {
            if (line.rfind("Error", 0) != 0) continue;
            errors += (errors.empty() ? "" : "; ") + line;
        }
        if (!errors.empty()) throw std::runtime_error(errors);
    }

   private:
    int threads_;
};

double signed_area(const std::vector<double>& rz, const int* quad) {
    double twice = 0.0;
    for (int a = 0; a < 4; ++a) {
        const int p = quad[a], q = quad[(a + 1) % 4];
        twice += rz[2 * p] * rz[2 * q + 1] - rz[2 * q] * rz[2 * p + 1];
    }
    return 0.5 * twice;
}

// Nodes of the current gmsh model that the quads use, numbered 0..n-1 by (z, r) so the
// numbering is deterministic and banded along the axis. Fills mesh.coordinates.
std::vector<int> number_nodes(const std::vector<std::size_t>& quad_node_tags, PileMesh& mesh) {
    std::vector<std::size_t> tags;
    std::vector<double> xyz, parametric;
    gmsh::model::mesh::getNodes(tags, xyz, parametric, -1, -1, false, false);
    std::size_t max_tag = 0;
    for (std::size_t t : tags) max_tag = std::max(max_tag, t);
    std::vector<long> slot(max_tag + 1, -1);  // gmsh tag -> position in `tags`
    for (std::size_t k = 0; k < tags.size(); ++k) slot[tags[k]] = static_cast<long>(k);

    std::vector<std::size_t> used;
    std::vector<bool> seen(max_tag + 1, false);
    for (std::size_t t : quad_node_tags) {
        if (t > max_tag || slot[t] < 0) throw std::runtime_error("quad refers to an unknown node");
        if (!seen[t]) used.push_back(t);
        seen[t] = true;
    }
    auto r = [&](std::size_t t) { return xyz[3 * slot[t]]; };
    auto z = [&](std::size_t t) { return xyz[3 * slot[t] + 1]; };
    std::sort(used.begin(), used.end(), [&](std::size_t a, std::size_t b) {
        return std::pair(z(a), r(a)) < std::pair(z(b), r(b));
    });

    std::vector<int> index(max_tag + 1, -1);  // gmsh tag -> our node number
    mesh.coordinates.clear();
    for (std::size_t k = 0; k < used.size(); ++k) {
        index[used[k]] = static_cast<int>(k);
        mesh.coordinates.push_back(r(used[k]));
        mesh.coordinates.push_back(z(used[k]));
    }
    return index;
}

// Quads of the current gmsh model, counter-clockwise in (r, z).
ElementBlock read_quads(const std::vector<std::size_t>& quad_node_tags,
                        const std::vector<int>& index, const std::vector<double>& rz) {
    ElementBlock block;
    block.kind = ElementKind::AxisymQuad4;
    block.nodes_per_element = 4;
    block.connectivity.reserve(quad_node_tags.size());
    for (std::size_t t : quad_node_tags) block.connectivity.push_back(index[t]);
    for (std::size_t e = 0; e < block.connectivity.size(); e += 4) {
        int* quad = &block.connectivity[e];
        if (signed_area(rz, quad) < 0.0) std::swap(quad[1], quad[3]);  // clockwise: reverse
        if (!(signed_area(rz, quad) > 0.0)) throw std::runtime_error("degenerate quad in the mesh");
    }
    return block;
}

// Nodes at elevation z_end (within 1e-9 L), sorted by r; their z is snapped to z_end so
// boundary conditions see the exact pile ends.
std::vector<int> end_nodes(PileMesh& mesh, double z_end, double length) {
    std::vector<int> nodes;
    for (int n = 0; n < mesh.num_nodes(); ++n) {
        if (std::abs(mesh.coordinates[2 * n + 1] - z_end) > 1e-9 * length) continue;
        mesh.coordinates[2 * n + 1] = z_end;
        nodes.push_back(n);
    }
    std::sort(nodes.begin(), nodes.end(),
              [&](int a, int b) { return mesh.coordinates[2 * a] < mesh.coordinates[2 * b]; });
    return nodes;
}

// The 2D mesh gmsh generated, as a PileMesh.
PileMesh read_wall_mesh(double length) {
    std::vector<int> types;
    gmsh::model::mesh::getElementTypes(types, 2, -1);
    if (std::any_of(types.begin(), types.end(), [](int t) { return t != kGmshQuad4; }))
        throw std::runtime_error("the wall mesh has elements other than 4-node quads");
    std::vector<std::size_t> element_tags, node_tags;
    gmsh::model::mesh::getElementsByType(kGmshQuad4, element_tags, node_tags, -1);
    if (element_tags.empty()) throw std::runtime_error("gmsh generated no quads");

    PileMesh mesh;
    mesh.dim = 2;
    const std::vector<int> index = number_nodes(node_tags, mesh);
    mesh.blocks.push_back(read_quads(node_tags, index, mesh.coordinates));
    mesh.toe_nodes = end_nodes(mesh, 0.0, length);
    mesh.head_nodes = end_nodes(mesh, length, length);
    if (mesh.toe_nodes.empty() || mesh.head_nodes.empty())
        throw std::runtime_error("the wall mesh does not reach both pile ends");
    return mesh;
}

PileMesh run_gmsh(const PileGeometry& geometry, const std::string& parameters,
                  const std::string& geo_file) {
    const TemporaryFile parameter_file(parameters);
    const GmshSession session;
    gmsh::merge(parameter_file.path());  // the parser keeps these variables for the next merge
    gmsh::merge(geo_file);
    session.throw_if_errors();
    gmsh::model::mesh::generate(2);
    session.throw_if_errors();
    return read_wall_mesh(geometry.length());
}

}  // namespace

PileMesh mesh_axisymmetric_wall(const PileGeometry& geometry, double element_size,
                                int radial_divisions, const std::string& geo_file) {
    validate(geometry, element_size, radial_divisions);
    const std::string where = "meshing the pile wall with '" + geo_file + "': ";
    std::error_code ec;
    if (!std::filesystem::is_regular_file(geo_file, ec))
        throw std::runtime_error(where + "file not found");
    const std::string parameters =
        parameter_script(geometry, axial_divisions(geometry, element_size), radial_divisions);
    // gmsh reports some failures as std::string or int; give the caller one exception type.
    try {
        return run_gmsh(geometry, parameters, geo_file);
    } catch (const std::exception& e) {
        throw std::runtime_error(where + e.what());
    } catch (const std::string& s) {
        throw std::runtime_error(where + s);
    } catch (...) {
        throw std::runtime_error(where + "gmsh failed");
    }
}

std::string default_pile_wall_geo() {
    const std::string file = "pile_wall_axisymmetric.geo";
    if (const char* dir = std::getenv("PILEMPM_MESH_DIR"); dir != nullptr && *dir != '\0')
        return (std::filesystem::path(dir) / file).string();
#ifdef PILEMPM_MESH_DIR_DEFAULT
    return (std::filesystem::path(PILEMPM_MESH_DIR_DEFAULT) / file).string();
#else
    return (std::filesystem::path("meshes") / file).string();
#endif
}

}  // namespace pilempm::fem
