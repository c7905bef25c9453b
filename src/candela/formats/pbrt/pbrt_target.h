#pragma once
// What the parser calls, one function per pbrt-v4 directive (pbrt-v4's ParserTarget, file format
// docs: https://pbrt.org/fileformat-v4). The parser (pbrt_parser.h) handles the syntax, Include
// and Import; a target gives the directives meaning (pbrt_importer.h builds a candela scene).
// Numbers arrive as double, exactly as written (the importer rounds to float where pbrt-v4 does).
#include <array>
#include <string>

#include "candela/formats/pbrt/pbrt_location.h"
#include "candela/formats/pbrt/pbrt_parameters.h"

namespace candela::pbrt {

class Target {
  public:
    virtual ~Target() = default;

    // Transforms and the graphics state
    virtual void identity(const Location& at) = 0;
    virtual void translate(double dx, double dy, double dz, const Location& at) = 0;
    virtual void scale(double sx, double sy, double sz, const Location& at) = 0;
    virtual void rotate(double angle_degrees, double ax, double ay, double az, const Location& at) = 0;
    virtual void look_at(double ex, double ey, double ez, double lx, double ly, double lz, double ux, double uy,
                         double uz, const Location& at) = 0;
    // The 16 numbers as written (pbrt's column-major order: m[12..14] is the translation).
    virtual void concat_transform(const std::array<double, 16>& m, const Location& at) = 0;
    virtual void transform(const std::array<double, 16>& m, const Location& at) = 0;
    virtual void coordinate_system(const std::string& name, const Location& at) = 0;
    virtual void coord_sys_transform(const std::string& name, const Location& at) = 0;
    virtual void active_transform(const std::string& which, const Location& at) = 0;  // All, StartTime, EndTime
    virtual void transform_times(double start, double end, const Location& at) = 0;
    virtual void reverse_orientation(const Location& at) = 0;
    virtual void attribute_begin(const Location& at) = 0;  // also TransformBegin (the parser warns)
    virtual void attribute_end(const Location& at) = 0;    // also TransformEnd
    virtual void attribute(const std::string& target, ParameterList params, const Location& at) = 0;

    // Rendering options (before WorldBegin)
    virtual void option(const std::string& name, const Parameter& value, const Location& at) = 0;
    virtual void color_space(const std::string& name, const Location& at) = 0;
    virtual void camera(const std::string& type, ParameterList params, const Location& at) = 0;
    virtual void film(const std::string& type, ParameterList params, const Location& at) = 0;
    virtual void pixel_filter(const std::string& type, ParameterList params, const Location& at) = 0;
    virtual void sampler(const std::string& type, ParameterList params, const Location& at) = 0;
    virtual void integrator(const std::string& type, ParameterList params, const Location& at) = 0;
    virtual void accelerator(const std::string& type, ParameterList params, const Location& at) = 0;
    virtual void make_named_medium(const std::string& name, ParameterList params, const Location& at) = 0;
    virtual void medium_interface(const std::string& inside, const std::string& outside, const Location& at) = 0;
    virtual void world_begin(const Location& at) = 0;

    // The world
    virtual void texture(const std::string& name, const std::string& value_type, const std::string& type,
                         ParameterList params, const Location& at) = 0;
    virtual void material(const std::string& type, ParameterList params, const Location& at) = 0;
    virtual void make_named_material(const std::string& name, ParameterList params, const Location& at) = 0;
    virtual void named_material(const std::string& name, const Location& at) = 0;
    virtual void light_source(const std::string& type, ParameterList params, const Location& at) = 0;
    virtual void area_light_source(const std::string& type, ParameterList params, const Location& at) = 0;
    virtual void shape(const std::string& type, ParameterList params, const Location& at) = 0;
    virtual void object_begin(const std::string& name, const Location& at) = 0;
    virtual void object_end(const Location& at) = 0;
    virtual void object_instance(const std::string& name, const Location& at) = 0;

    // After the last directive of the main file.
    virtual void end_of_files() = 0;
    // A warning of the parser's own (TransformBegin is deprecated, ...), already located.
    virtual void warn(const Location& at, const std::string& message) = 0;
};

}  // namespace candela::pbrt
