#pragma once
// A Target that does nothing with the directives, for measuring the parser alone (bench/) and
// for fuzzing it (fuzz/): every directive's parameters go to one hook, parameters(), which a
// subclass may override to look at them.
#include "candela/formats/pbrt/pbrt_target.h"

namespace candela::pbrt {

class NullTarget : public Target {
  public:
    virtual void parameters(const ParameterList&) {}

    void identity(const Location&) override {}
    void translate(double, double, double, const Location&) override {}
    void scale(double, double, double, const Location&) override {}
    void rotate(double, double, double, double, const Location&) override {}
    void look_at(double, double, double, double, double, double, double, double, double, const Location&) override {}
    void concat_transform(const std::array<double, 16>&, const Location&) override {}
    void transform(const std::array<double, 16>&, const Location&) override {}
    void coordinate_system(const std::string&, const Location&) override {}
    void coord_sys_transform(const std::string&, const Location&) override {}
    void active_transform(const std::string&, const Location&) override {}
    void transform_times(double, double, const Location&) override {}
    void reverse_orientation(const Location&) override {}
    void attribute_begin(const Location&) override {}
    void attribute_end(const Location&) override {}
    void attribute(const std::string&, ParameterList p, const Location&) override { parameters(p); }
    void option(const std::string&, const Parameter& value, const Location&) override { parameters({value}); }
    void color_space(const std::string&, const Location&) override {}
    void camera(const std::string&, ParameterList p, const Location&) override { parameters(p); }
    void film(const std::string&, ParameterList p, const Location&) override { parameters(p); }
    void pixel_filter(const std::string&, ParameterList p, const Location&) override { parameters(p); }
    void sampler(const std::string&, ParameterList p, const Location&) override { parameters(p); }
    void integrator(const std::string&, ParameterList p, const Location&) override { parameters(p); }
    void accelerator(const std::string&, ParameterList p, const Location&) override { parameters(p); }
    void make_named_medium(const std::string&, ParameterList p, const Location&) override { parameters(p); }
    void medium_interface(const std::string&, const std::string&, const Location&) override {}
    void world_begin(const Location&) override {}
    void texture(const std::string&, const std::string&, const std::string&, ParameterList p,
                 const Location&) override {
        parameters(p);
    }
    void material(const std::string&, ParameterList p, const Location&) override { parameters(p); }
    void make_named_material(const std::string&, ParameterList p, const Location&) override { parameters(p); }
    void named_material(const std::string&, const Location&) override {}
    void light_source(const std::string&, ParameterList p, const Location&) override { parameters(p); }
    void area_light_source(const std::string&, ParameterList p, const Location&) override { parameters(p); }
    void shape(const std::string&, ParameterList p, const Location&) override { parameters(p); }
    void object_begin(const std::string&, const Location&) override {}
    void object_end(const Location&) override {}
    void object_instance(const std::string&, const Location&) override {}
    void end_of_files() override {}
    void warn(const Location&, const std::string&) override {}
};

}  // namespace candela::pbrt
