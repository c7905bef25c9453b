#include "candela/media/scattering_presets.h"

#include <array>

namespace candela {

namespace {

// {name, sigma_s', sigma_a}, per mm, in pbrt-v4's order (src/pbrt/media.cpp,
// SubsurfaceParameterTable); the first twelve from Jensen et al. 2001, the rest from Narasimhan
// et al. 2006.
constexpr std::array kPresets = {
    ScatteringPreset{"Apple", Rgb(2.29f, 2.39f, 1.97f), Rgb(0.0030f, 0.0034f, 0.046f)},
    ScatteringPreset{"Chicken1", Rgb(0.15f, 0.21f, 0.38f), Rgb(0.015f, 0.077f, 0.19f)},
    ScatteringPreset{"Chicken2", Rgb(0.19f, 0.25f, 0.32f), Rgb(0.018f, 0.088f, 0.20f)},
    ScatteringPreset{"Cream", Rgb(7.38f, 5.47f, 3.15f), Rgb(0.0002f, 0.0028f, 0.0163f)},
    ScatteringPreset{"Ketchup", Rgb(0.18f, 0.07f, 0.03f), Rgb(0.061f, 0.97f, 1.45f)},
    ScatteringPreset{"Marble", Rgb(2.19f, 2.62f, 3.00f), Rgb(0.0021f, 0.0041f, 0.0071f)},
    ScatteringPreset{"Potato", Rgb(0.68f, 0.70f, 0.55f), Rgb(0.0024f, 0.0090f, 0.12f)},
    ScatteringPreset{"Skimmilk", Rgb(0.70f, 1.22f, 1.90f), Rgb(0.0014f, 0.0025f, 0.0142f)},
    ScatteringPreset{"Skin1", Rgb(0.74f, 0.88f, 1.01f), Rgb(0.032f, 0.17f, 0.48f)},
    ScatteringPreset{"Skin2", Rgb(1.09f, 1.59f, 1.79f), Rgb(0.013f, 0.070f, 0.145f)},
    ScatteringPreset{"Spectralon", Rgb(11.6f, 20.4f, 14.9f), Rgb(0.00f, 0.00f, 0.00f)},
    ScatteringPreset{"Wholemilk", Rgb(2.55f, 3.21f, 3.77f), Rgb(0.0011f, 0.0024f, 0.014f)},
    ScatteringPreset{"Lowfat Milk", Rgb(0.89187f, 1.5136f, 2.532f), Rgb(0.002875f, 0.00575f, 0.0115f)},
    ScatteringPreset{"Reduced Milk", Rgb(2.4858f, 3.1669f, 4.5214f), Rgb(0.0025556f, 0.0051111f, 0.012778f)},
    ScatteringPreset{"Regular Milk", Rgb(4.5513f, 5.8294f, 7.136f), Rgb(0.0015333f, 0.0046f, 0.019933f)},
    ScatteringPreset{"Espresso", Rgb(0.72378f, 0.84557f, 1.0247f), Rgb(4.7984f, 6.5751f, 8.8493f)},
    ScatteringPreset{"Mint Mocha Coffee", Rgb(0.31602f, 0.38538f, 0.48131f), Rgb(3.772f, 5.8228f, 7.82f)},
    ScatteringPreset{"Lowfat Soy Milk", Rgb(0.30576f, 0.34233f, 0.61664f), Rgb(0.0014375f, 0.0071875f, 0.035937f)},
    ScatteringPreset{"Regular Soy Milk", Rgb(0.59223f, 0.73866f, 1.4693f), Rgb(0.0019167f, 0.0095833f, 0.065167f)},
    ScatteringPreset{"Lowfat Chocolate Milk", Rgb(0.64925f, 0.83916f, 1.1057f), Rgb(0.0115f, 0.0368f, 0.1564f)},
    ScatteringPreset{"Regular Chocolate Milk", Rgb(1.4585f, 2.1289f, 2.9527f), Rgb(0.010063f, 0.043125f, 0.14375f)},
    ScatteringPreset{"Coke", Rgb(8.9053e-05f, 8.372e-05f, 0.0f), Rgb(0.10014f, 0.16503f, 0.2468f)},
    ScatteringPreset{"Pepsi", Rgb(6.1697e-05f, 4.2564e-05f, 0.0f), Rgb(0.091641f, 0.14158f, 0.20729f)},
    ScatteringPreset{"Sprite", Rgb(6.0306e-06f, 6.4139e-06f, 6.5504e-06f), Rgb(0.001886f, 0.0018308f, 0.0020025f)},
    ScatteringPreset{"Gatorade", Rgb(0.0024574f, 0.003007f, 0.0037325f), Rgb(0.024794f, 0.019289f, 0.008878f)},
    ScatteringPreset{"Chardonnay", Rgb(1.7982e-05f, 1.3758e-05f, 1.2023e-05f), Rgb(0.010782f, 0.011855f, 0.023997f)},
    ScatteringPreset{"White Zinfandel", Rgb(1.7501e-05f, 1.9069e-05f, 1.288e-05f), Rgb(0.012072f, 0.016184f, 0.019843f)},
    ScatteringPreset{"Merlot", Rgb(2.1129e-05f, 0.0f, 0.0f), Rgb(0.11632f, 0.25191f, 0.29434f)},
    ScatteringPreset{"Budweiser Beer", Rgb(2.4356e-05f, 2.4079e-05f, 1.0564e-05f), Rgb(0.011492f, 0.024911f, 0.057786f)},
    ScatteringPreset{"Coors Light Beer", Rgb(5.0922e-05f, 4.301e-05f, 0.0f), Rgb(0.006164f, 0.013984f, 0.034983f)},
    ScatteringPreset{"Clorox", Rgb(0.0024035f, 0.0031373f, 0.003991f), Rgb(0.0033542f, 0.014892f, 0.026297f)},
    ScatteringPreset{"Apple Juice", Rgb(0.00013612f, 0.00015836f, 0.000227f), Rgb(0.012957f, 0.023741f, 0.052184f)},
    ScatteringPreset{"Cranberry Juice", Rgb(0.00010402f, 0.00011646f, 7.8139e-05f), Rgb(0.039437f, 0.094223f, 0.12426f)},
    ScatteringPreset{"Grape Juice", Rgb(5.382e-05f, 0.0f, 0.0f), Rgb(0.10404f, 0.23958f, 0.29325f)},
    ScatteringPreset{"Ruby Grapefruit Juice", Rgb(0.011002f, 0.010927f, 0.011036f), Rgb(0.085867f, 0.18314f, 0.25262f)},
    ScatteringPreset{"White Grapefruit Juice", Rgb(0.22826f, 0.23998f, 0.32748f), Rgb(0.0138f, 0.018831f, 0.056781f)},
    ScatteringPreset{"Shampoo", Rgb(0.0007176f, 0.0008303f, 0.0009016f), Rgb(0.014107f, 0.045693f, 0.061717f)},
    ScatteringPreset{"Strawberry Shampoo", Rgb(0.00015671f, 0.00015947f, 1.518e-05f), Rgb(0.01449f, 0.05796f, 0.075823f)},
    ScatteringPreset{"Head & Shoulders Shampoo", Rgb(0.023805f, 0.028804f, 0.034306f), Rgb(0.084621f, 0.15688f, 0.20365f)},
    ScatteringPreset{"Lemon Tea Powder", Rgb(0.040224f, 0.045264f, 0.051081f), Rgb(2.4288f, 4.5757f, 7.2127f)},
    ScatteringPreset{"Orange Powder", Rgb(0.00015617f, 0.00017482f, 0.0001762f), Rgb(0.001449f, 0.003441f, 0.007863f)},
    ScatteringPreset{"Pink Lemonade Powder", Rgb(0.00012103f, 0.00013073f, 0.00012528f), Rgb(0.001165f, 0.002366f, 0.003195f)},
    ScatteringPreset{"Cappuccino Powder", Rgb(1.8436f, 2.5851f, 2.1662f), Rgb(35.844f, 49.547f, 61.084f)},
    ScatteringPreset{"Salt Powder", Rgb(0.027333f, 0.032451f, 0.031979f), Rgb(0.28415f, 0.3257f, 0.34148f)},
    ScatteringPreset{"Sugar Powder", Rgb(0.00022272f, 0.00025513f, 0.000271f), Rgb(0.012638f, 0.031051f, 0.050124f)},
    ScatteringPreset{"Suisse Mocha Powder", Rgb(2.7979f, 3.5452f, 4.3365f), Rgb(17.502f, 27.004f, 35.433f)},
};

}  // namespace

std::span<const ScatteringPreset> scattering_presets() { return kPresets; }

std::vector<std::string_view> scattering_preset_names() {
    std::vector<std::string_view> names;
    for (const ScatteringPreset& p : kPresets) names.push_back(p.name);
    return names;
}

std::optional<ScatteringPreset> find_scattering_preset(std::string_view name) {
    for (const ScatteringPreset& p : kPresets)
        if (p.name == name) return p;
    return std::nullopt;
}

}  // namespace candela
