// `skylit spheres-fit`: fits K spheres to a closed mesh (an OBJ/PLY file or a built-in
// procedural aircraft) by k-means, prints how far they are from it, and writes the
// sphere set as JSON (optionally the mesh as OBJ and a picture as SVG).
#include "app/commands.h"
#include "app/common/text_file.h"
#include "app/flight/fit_svg.h"

#include "flight/aircraft_mesh.h"
#include "flight/mesh_io.h"
#include "flight/sphere_fit.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

namespace skylit::app::flight {
namespace {

namespace fl = skylit::flight;

struct FitArgs {
  std::string mesh_path, aircraft, output, write_mesh, svg, name;
  fl::FitOptions fit;
  std::string radius_rule = "shell";
  bool overwrite = false;
  bool quiet = false;
};

fl::RadiusRule radius_rule(const std::string& name) {
  if (name == "volume") return fl::RadiusRule::kVolumeShare;
  if (name == "planform") return fl::RadiusRule::kPlanformArea;
  return fl::RadiusRule::kHalfSolidShell;
}

void refuse_existing(const std::string& path, bool overwrite) {
  std::error_code ec;
  if (!path.empty() && std::filesystem::exists(path, ec) && !overwrite)
    throw std::invalid_argument("output '" + path + "' exists; pass --overwrite to replace it");
}

std::string percent(double fraction) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f%%", 100.0 * fraction);
  return buf;
}

void print_report(const fl::SphereFit& fit, const fl::Bounds& box) {
  const auto& v = fit.report.volume;
  std::printf("spheres: %zu (%d Lloyd iterations); mesh %.2f x %.2f x %.2f m (length x span x height)\n",
              fit.spheres.size(), fit.iterations, box.size().x, box.size().y, box.size().z);
  std::printf("volume: mesh %.4g m3, spheres %.4g m3; symmetric difference %.4g m3 = %s of the mesh (se %s, %lld points)\n",
              v.volume_a, v.volume_b, v.symmetric_difference, percent(v.relative).c_str(), percent(v.relative_se).c_str(),
              v.samples);
  for (const auto& s : fit.report.views)
    std::printf("solid angle %-17s mesh %.4e sr, spheres %.4e sr: %+.2f%% (se %.2f%%), mismatched %.2f%% (%lld rays)\n",
                (s.view.label + ":").c_str(), s.mesh_sr, s.spheres_sr, 100.0 * s.relative(),
                s.mesh_sr > 0 ? 100.0 * s.difference_se_sr / s.mesh_sr : 0.0,
                s.mesh_sr > 0 ? 100.0 * s.mismatch_sr / s.mesh_sr : 0.0, s.rays);
}

int run_spheres_fit(FitArgs a) {
  if (a.mesh_path.empty() == a.aircraft.empty())
    throw std::invalid_argument("give either a MESH file or --aircraft NAME");
  refuse_existing(a.output, a.overwrite);
  refuse_existing(a.write_mesh, a.overwrite);
  refuse_existing(a.svg, a.overwrite);
  check_writable(a.output, "sphere set");
  if (!a.write_mesh.empty()) check_writable(a.write_mesh, "mesh");
  if (!a.svg.empty()) check_writable(a.svg, "picture");
  a.fit.radius_rule = radius_rule(a.radius_rule);

  const fl::Mesh mesh = a.aircraft.empty() ? fl::read_mesh(a.mesh_path) : fl::make_aircraft_mesh(a.aircraft);
  const std::string what = a.aircraft.empty() ? a.mesh_path : "aircraft '" + a.aircraft + "'";
  fl::check_closed_mesh(mesh, what);
  const fl::SphereFit fit = fl::fit_spheres(mesh, a.fit);
  const fl::Bounds box = fl::bounds(mesh);

  fl::SphereSet set;
  set.name = !a.name.empty() ? a.name
             : !a.aircraft.empty() ? a.aircraft
                                   : std::filesystem::path(a.mesh_path).stem().string();
  set.spheres = fit.spheres;
  set.length_m = box.size().x;
  set.span_m = box.size().y;
  set.height_m = box.size().z;
  const std::string& rule = a.radius_rule;
  set.source = (a.aircraft.empty() ? "mesh " + std::filesystem::path(a.mesh_path).filename().string()
                                   : "procedural aircraft '" + a.aircraft + "' (flight/aircraft_mesh.cpp)") +
               "; skylit spheres-fit -k " + std::to_string(a.fit.k) + " --seed " + std::to_string(a.fit.seed) +
               " --samples " + std::to_string(a.fit.samples) + " --radius " + rule;
  set.has_fit_error = true;
  set.fit_error = fit.report.summary();

  if (!a.quiet) print_report(fit, box);
  write_text_atomically(a.output, fl::sphere_set_json(set), "sphere set");
  if (!a.write_mesh.empty()) write_text_atomically(a.write_mesh, fl::obj_text(mesh, "skylit: " + what), "mesh");
  if (!a.svg.empty())
    write_text_atomically(a.svg,
                          fit_svg(mesh, fit.spheres,
                                  set.name + ": " + std::to_string(fit.spheres.size()) + " spheres, volume error " +
                                      percent(fit.report.volume.relative) + ", solid-angle error " +
                                      percent(fit.report.worst_solid_angle_error())),
                          "picture");
  if (!a.quiet) std::cerr << "skylit: wrote " << a.output << "\n";
  return 0;
}

}  // namespace

void add_spheres_fit_command(CLI::App& root, Action& run) {
  auto args = std::make_shared<FitArgs>();
  CLI::App* cmd = root.add_subcommand("spheres-fit", "Fit K spheres to a closed mesh (OBJ, PLY or a built-in aircraft) by k-means");
  cmd->add_option("mesh", args->mesh_path, "Closed mesh (.obj or .ply), body frame: x forward, y left, z up, metres");
  std::string names;
  for (const auto& p : fl::aircraft_presets()) names += (names.empty() ? "" : ", ") + p.name;
  cmd->add_option("--aircraft", args->aircraft, "A built-in procedural aircraft instead of a mesh: " + names);
  cmd->add_option("-k", args->fit.k, "Number of spheres")->check(CLI::Range(1, static_cast<int>(fl::kMaxSpheres)))->capture_default_str();
  cmd->add_option("-o,--output", args->output, "Sphere set (JSON)")->required();
  cmd->add_option("--seed", args->fit.seed, "Seed of the sampling and the k-means++ start")->capture_default_str();
  cmd->add_option("--samples", args->fit.samples, "Points inside the mesh for the clustering")
      ->check(CLI::Range(1LL, 100'000'000LL))->capture_default_str();
  cmd->add_option("--error-samples", args->fit.error_samples, "Points for the volume error")
      ->check(CLI::Range(1LL, 1'000'000'000LL))->capture_default_str();
  cmd->add_option("--error-rays", args->fit.error_rays, "Rays per viewpoint for the solid-angle error")
      ->check(CLI::Range(1LL, 1'000'000'000LL))->capture_default_str();
  cmd->add_option("--radius", args->radius_rule,
                  "Radius rule: shell (half the sphere's surface in the solid), volume (volume share) or planform "
                  "(the disc of the cluster's area seen from above: thin wings for shadows below)")
      ->check(CLI::IsMember({"shell", "volume", "planform"}))->capture_default_str();
  cmd->add_option("--name", args->name, "Name in the set (default: the aircraft or the mesh file's stem)");
  cmd->add_option("--write-mesh", args->write_mesh, "Also write the mesh as OBJ");
  cmd->add_option("--svg", args->svg, "Also write a picture: top and side views, spheres over the mesh");
  cmd->add_flag("--overwrite", args->overwrite, "Replace outputs that exist");
  cmd->add_flag("-q,--quiet", args->quiet, "No report");
  cmd->callback([&run, args] { run = [args] { return run_spheres_fit(*args); }; });
}

}  // namespace skylit::app::flight
