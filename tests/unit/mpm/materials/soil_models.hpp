#pragma once
// Every built-in soil model with representative parameters, for the tests that must hold
// for all of them (objectivity, robustness at extreme stresses).
#include <functional>
#include <memory>
#include <vector>

#include "mpm/materials/hardening_soil_small.hpp"
#include "mpm/materials/hypoplastic.hpp"
#include "mpm/materials/modified_cam_clay.hpp"
#include "mpm/materials/mohr_coulomb.hpp"
#include "mpm/materials/mu_i_rheology.hpp"
#include "mpm/materials/subloading_cam_clay.hpp"

namespace pilempm::mpm::test_models {

using ModelFactory = std::function<std::unique_ptr<ConstitutiveModel>()>;

inline std::vector<ModelFactory> all_soil_models() {
    return {
        [] { return std::make_unique<LinearElastic>(50e6, 0.3); },
        [] { return std::make_unique<MohrCoulomb>(50e6, 0.3, 30.0, 5.0, 1e3, 0.0); },
        [] {
            CamClayParameters p;
            p.ocr = 1.5;
            return std::make_unique<ModifiedCamClay>(p);
        },
        [] {
            SubloadingCamClayParameters p;
            p.ocr = 2.0;
            return std::make_unique<SubloadingCamClay>(p);
        },
        [] { return std::make_unique<Hypoplastic>(HypoplasticParameters{}); },  // with intergranular strain
        [] { return std::make_unique<HardeningSoilSmall>(HardeningSoilSmallParameters{}); },  // strain history H
        [] { return std::make_unique<MuIRheology>(MuIParameters{}); },
    };
}

}  // namespace pilempm::mpm::test_models
