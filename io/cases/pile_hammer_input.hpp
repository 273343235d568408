#pragma once
// The pile and hammer sections every analysis shares, as read from a case file (SI units,
// validated), and their readers.
#include <map>
#include <string>
#include <vector>

#include "fem/hammer/hammer.hpp"
#include "fem/dynamics/explicit_pile.hpp"
#include "fem/mesh/pile_geometry.hpp"
#include "io/yaml/yaml_reader.hpp"

namespace pilempm::io {

enum class PileModel { Rod, Axisymmetric };
const char* pile_model_name(PileModel m);

struct CaseFile {
    std::string file;   // the case file, for messages
    std::string title;
    double gravity = 9.81;
    std::map<std::string, int> lines;  // key path -> line, for errors found after reading
    int line_of(const std::string& key) const {
        auto it = lines.find(key);
        return it == lines.end() ? 0 : it->second;
    }
};

struct PileInput {
    PileModel model = PileModel::Rod;
    std::vector<fem::PileSegment> segments;  // head to toe
    double taper_ratio = 4.0;
    fem::LinearElasticSteel steel;
    double element_size = 0.0;   // m
    int radial_divisions = 2;    // axisymmetric
    fem::ToeSupport toe;
    bool toe_impedance_given = false;  // else: the pile's own impedance
    double length() const;
};

struct HammerInput {
    fem::HammerSpec hammer;
    std::string hammer_description;
    double rated_energy = 0.0;   // J, m g h of the hammer when known
    double hammer_mass = 0.0;    // kg resting on the pile (ram + helmet) when known
};

// title, analysis (must be `analysis`) and gravity of the top level.
void read_case_header(MapReader& root, CaseFile& c, const std::string& file, const std::string& analysis);

// `pile:`; with_toe: the toe condition is asked for (pile wave analysis), else the soil
// supports the toe and a `toe` key is an error.
void read_pile_section(MapReader m, PileInput& pile, CaseFile& c, bool with_toe);
void read_hammer_section(MapReader m, HammerInput& hammer, const CaseFile& c);

}  // namespace pilempm::io
