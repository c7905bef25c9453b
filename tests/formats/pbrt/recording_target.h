#pragma once
// A pbrt Target that logs every call as one line, "Directive args {type name: values} @line:col",
// so that tests can compare what the parser handed over with what they expect.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>
#include <string>
#include <vector>

#include "candela/formats/pbrt/pbrt_target.h"

namespace candela::pbrt::test {

inline std::string format_parameters(const ParameterList& params) {
    std::string out;
    for (const Parameter& p : params) {
        out += " {" + p.type + " " + p.name + ":";
        for (double x : p.numbers) out += fmt::format(" {}", x);
        for (const std::string& s : p.strings) out += " \"" + s + "\"";
        for (uint8_t b : p.bools) out += b ? " true" : " false";
        out += "}";
    }
    return out;
}

class RecordingTarget : public Target {
  public:
    std::vector<std::string> log;
    std::vector<std::string> warnings;
    std::vector<Location> locations;  // of every directive, in order
    std::vector<ParameterList> parameter_lists;
    bool ended = false;

    void identity(const Location& at) override { add("Identity", at); }
    void translate(double x, double y, double z, const Location& at) override {
        add(fmt::format("Translate {} {} {}", x, y, z), at);
    }
    void scale(double x, double y, double z, const Location& at) override {
        add(fmt::format("Scale {} {} {}", x, y, z), at);
    }
    void rotate(double a, double x, double y, double z, const Location& at) override {
        add(fmt::format("Rotate {} {} {} {}", a, x, y, z), at);
    }
    void look_at(double ex, double ey, double ez, double lx, double ly, double lz, double ux, double uy, double uz,
                 const Location& at) override {
        add(fmt::format("LookAt {} {} {} {} {} {} {} {} {}", ex, ey, ez, lx, ly, lz, ux, uy, uz), at);
    }
    void concat_transform(const std::array<double, 16>& m, const Location& at) override {
        add(fmt::format("ConcatTransform {}", fmt::join(m, " ")), at);
    }
    void transform(const std::array<double, 16>& m, const Location& at) override {
        add(fmt::format("Transform {}", fmt::join(m, " ")), at);
    }
    void coordinate_system(const std::string& name, const Location& at) override {
        add("CoordinateSystem " + name, at);
    }
    void coord_sys_transform(const std::string& name, const Location& at) override {
        add("CoordSysTransform " + name, at);
    }
    void active_transform(const std::string& which, const Location& at) override {
        add("ActiveTransform " + which, at);
    }
    void transform_times(double start, double end, const Location& at) override {
        add(fmt::format("TransformTimes {} {}", start, end), at);
    }
    void reverse_orientation(const Location& at) override { add("ReverseOrientation", at); }
    void attribute_begin(const Location& at) override { add("AttributeBegin", at); }
    void attribute_end(const Location& at) override { add("AttributeEnd", at); }
    void attribute(const std::string& target, ParameterList params, const Location& at) override {
        add("Attribute " + target, at, std::move(params));
    }
    void option(const std::string& name, const Parameter& value, const Location& at) override {
        add("Option " + name, at, ParameterList{value});
    }
    void color_space(const std::string& name, const Location& at) override { add("ColorSpace " + name, at); }
    void camera(const std::string& type, ParameterList params, const Location& at) override {
        add("Camera " + type, at, std::move(params));
    }
    void film(const std::string& type, ParameterList params, const Location& at) override {
        add("Film " + type, at, std::move(params));
    }
    void pixel_filter(const std::string& type, ParameterList params, const Location& at) override {
        add("PixelFilter " + type, at, std::move(params));
    }
    void sampler(const std::string& type, ParameterList params, const Location& at) override {
        add("Sampler " + type, at, std::move(params));
    }
    void integrator(const std::string& type, ParameterList params, const Location& at) override {
        add("Integrator " + type, at, std::move(params));
    }
    void accelerator(const std::string& type, ParameterList params, const Location& at) override {
        add("Accelerator " + type, at, std::move(params));
    }
    void make_named_medium(const std::string& name, ParameterList params, const Location& at) override {
        add("MakeNamedMedium " + name, at, std::move(params));
    }
    void medium_interface(const std::string& inside, const std::string& outside, const Location& at) override {
        add("MediumInterface \"" + inside + "\" \"" + outside + "\"", at);
    }
    void world_begin(const Location& at) override { add("WorldBegin", at); }
    void texture(const std::string& name, const std::string& value_type, const std::string& type, ParameterList params,
                 const Location& at) override {
        add("Texture " + name + " " + value_type + " " + type, at, std::move(params));
    }
    void material(const std::string& type, ParameterList params, const Location& at) override {
        add("Material " + type, at, std::move(params));
    }
    void make_named_material(const std::string& name, ParameterList params, const Location& at) override {
        add("MakeNamedMaterial " + name, at, std::move(params));
    }
    void named_material(const std::string& name, const Location& at) override { add("NamedMaterial " + name, at); }
    void light_source(const std::string& type, ParameterList params, const Location& at) override {
        add("LightSource " + type, at, std::move(params));
    }
    void area_light_source(const std::string& type, ParameterList params, const Location& at) override {
        add("AreaLightSource " + type, at, std::move(params));
    }
    void shape(const std::string& type, ParameterList params, const Location& at) override {
        add("Shape " + type, at, std::move(params));
    }
    void object_begin(const std::string& name, const Location& at) override { add("ObjectBegin " + name, at); }
    void object_end(const Location& at) override { add("ObjectEnd", at); }
    void object_instance(const std::string& name, const Location& at) override { add("ObjectInstance " + name, at); }
    void end_of_files() override { ended = true; }
    void warn(const Location& at, const std::string& message) override {
        warnings.push_back(describe(at) + ": " + message);
    }

  private:
    void add(const std::string& call, const Location& at, ParameterList params = {}) {
        log.push_back(call + format_parameters(params) + fmt::format(" @{}:{}", at.line, at.column));
        locations.push_back(at);
        parameter_lists.push_back(std::move(params));
    }
};

}  // namespace candela::pbrt::test
