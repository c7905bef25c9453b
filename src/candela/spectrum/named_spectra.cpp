#include "candela/spectrum/named_spectra.h"

#include <array>
#include <cstddef>

#include "candela/spectrum/cie_tables.h"
#include "candela/spectrum/named_spectra_data.h"

namespace candela {

namespace {

struct NamedTable {
    std::string_view name;
    std::span<const float> pairs;  // (nm, value), wavelengths increasing
    bool illuminant;               // scaled to luminance 1
};

// pbrt-v4's names (Spectra::Init in src/pbrt/util/spectrum.cpp), in its order. pbrt-v4 calls
// the SCHOTT flints SF5, SF10 and SF11 "glass-F5", "glass-F10" and "glass-F11"; their own names
// are accepted too. The camera sensors' curves (canon_eos_100d_r, ...) are left out: they
// describe a film's sensor, not a colour.
constexpr std::array kTables = {
    NamedTable{"metal-Ag-eta", kMetalAgEta, false},
    NamedTable{"metal-Ag-k", kMetalAgK, false},
    NamedTable{"metal-Al-eta", kMetalAlEta, false},
    NamedTable{"metal-Al-k", kMetalAlK, false},
    NamedTable{"metal-Au-eta", kMetalAuEta, false},
    NamedTable{"metal-Au-k", kMetalAuK, false},
    NamedTable{"metal-Cu-eta", kMetalCuEta, false},
    NamedTable{"metal-Cu-k", kMetalCuK, false},
    NamedTable{"metal-CuZn-eta", kMetalCuZnEta, false},
    NamedTable{"metal-CuZn-k", kMetalCuZnK, false},
    NamedTable{"metal-MgO-eta", kMetalMgOEta, false},
    NamedTable{"metal-MgO-k", kMetalMgOK, false},
    NamedTable{"metal-TiO2-eta", kMetalTiO2Eta, false},
    NamedTable{"metal-TiO2-k", kMetalTiO2K, false},
    NamedTable{"glass-BK7", kGlassBk7Eta, false},
    NamedTable{"glass-BAF10", kGlassBaf10Eta, false},
    NamedTable{"glass-FK51A", kGlassFk51aEta, false},
    NamedTable{"glass-LASF9", kGlassLasf9Eta, false},
    NamedTable{"glass-F5", kGlassSf5Eta, false},
    NamedTable{"glass-F10", kGlassSf10Eta, false},
    NamedTable{"glass-F11", kGlassSf11Eta, false},
    NamedTable{"glass-SF5", kGlassSf5Eta, false},
    NamedTable{"glass-SF10", kGlassSf10Eta, false},
    NamedTable{"glass-SF11", kGlassSf11Eta, false},
    NamedTable{"stdillum-A", kIllumA, true},
    NamedTable{"stdillum-D50", kIllumD50, true},
    NamedTable{"stdillum-D65", kCieIllumD65, true},
    NamedTable{"stdillum-F1", kIllumF1, true},
    NamedTable{"stdillum-F2", kIllumF2, true},
    NamedTable{"stdillum-F3", kIllumF3, true},
    NamedTable{"stdillum-F4", kIllumF4, true},
    NamedTable{"stdillum-F5", kIllumF5, true},
    NamedTable{"stdillum-F6", kIllumF6, true},
    NamedTable{"stdillum-F7", kIllumF7, true},
    NamedTable{"stdillum-F8", kIllumF8, true},
    NamedTable{"stdillum-F9", kIllumF9, true},
    NamedTable{"stdillum-F10", kIllumF10, true},
    NamedTable{"stdillum-F11", kIllumF11, true},
    NamedTable{"stdillum-F12", kIllumF12, true},
    NamedTable{"illum-acesD60", kIllumAcesD60, true},
};
constexpr std::string_view kD65Name = "stdillum-D65";

// pbrt-v4's PiecewiseLinearSpectrum::FromInterleaved sampled at every nm; an illuminant scaled
// by CIE_Y_integral / <spectrum, y-bar>, so that its luminance Y is 1.
DenseSpectrum build(const NamedTable& t) {
    DenseSpectrum s = dense_from_pairs(t.pairs);
    if (t.illuminant) s *= float(double(kCieYIntegral) / spectrum_to_photometric(s));
    return s;
}

const std::array<DenseSpectrum, kTables.size()>& spectra() {
    static const std::array<DenseSpectrum, kTables.size()> all = [] {
        std::array<DenseSpectrum, kTables.size()> a;
        for (size_t i = 0; i < kTables.size(); ++i) a[i] = build(kTables[i]);
        return a;
    }();
    return all;
}

}  // namespace

const DenseSpectrum* named_spectrum(std::string_view name) {
    // D65 is the colour space's white: the very same values, built once (dense_spectrum.cpp).
    if (name == kD65Name) return &d65_illuminant();
    for (size_t i = 0; i < kTables.size(); ++i)
        if (kTables[i].name == name) return &spectra()[i];
    return nullptr;
}

std::span<const std::string_view> named_spectrum_names() {
    static const std::array<std::string_view, kTables.size()> names = [] {
        std::array<std::string_view, kTables.size()> n;
        for (size_t i = 0; i < kTables.size(); ++i) n[i] = kTables[i].name;
        return n;
    }();
    return names;
}

}  // namespace candela
