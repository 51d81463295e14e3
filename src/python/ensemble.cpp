// Ensembles in Python: what the file says (cask, motions, measure, stripes) and the realisations
// it draws, as columns that rollout takes back (ensemble/rollout.h).

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "ensemble/ensemble_file.h"
#include "ensemble/limit_state_file.h"
#include "ensemble/rollout.h"
#include "python/bindings.h"
#include "python/convert.h"
#include "sim/simulate.h"

namespace caskdem::python {

namespace {

py::dict nominal_parameters(const Ensemble& e) {
  const RealisationParameters& p = e.plan.nominal();
  py::dict d;
  d["friction_static"] = p.friction_static;
  d["friction_kinetic"] = p.friction_kinetic;
  d["friction_decay_speed"] = p.friction_decay_speed;
  d["damping_ratio"] = p.damping_ratio;
  d["mass"] = p.mass;
  d["centre_height"] = p.centre_of_mass.y;
  d["eccentricity"] = p.centre_of_mass.x;
  d["base_camber"] = p.base_camber;
  return d;
}

py::dict motion_intensities(const Ensemble& e) {
  const int motions = e.plan.motion_count();
  std::vector<double> pga(motions), pgv(motions), sa(motions), duration(motions), run(motions);
  for (int k = 0; k < motions; ++k) {
    pga[k] = e.plan.intensity(k).pga;
    pgv[k] = e.plan.intensity(k).pgv;
    sa[k] = e.plan.intensity(k).sa;
    duration[k] = e.plan.intensity(k).duration;
    run[k] = e.plan.run_duration(k);
  }
  py::dict d;
  d["pga"] = array(pga);
  d["pgv"] = array(pgv);
  if (e.plan.spec().measure == IntensityMeasure::sa) d["sa"] = array(sa);
  d["duration"] = array(duration);
  d["run_duration"] = array(run);
  return d;
}

}  // namespace

void bind_ensemble(py::module_& m) {
  py::class_<Ensemble, std::shared_ptr<Ensemble>>(m, "Ensemble")
      .def_property_readonly("title", [](const Ensemble& e) { return e.plan.spec().title; })
      .def_property_readonly("name", [](const Ensemble& e) { return e.plan.spec().name; })
      .def_property_readonly("file", [](const Ensemble& e) { return e.plan.spec().file.string(); })
      .def_property_readonly("dimensions", [](const Ensemble& e) { return e.plan.three_d() ? 3 : 2; })
      .def_property_readonly("size", [](const Ensemble& e) { return e.plan.size(); })
      .def_property_readonly("motion_names", [](const Ensemble& e) { return e.plan.spec().motion_names; })
      .def_property_readonly("measure", [](const Ensemble& e) { return intensity_name(e.plan.spec().measure); })
      .def_property_readonly("measure_unit", [](const Ensemble& e) { return intensity_si_unit(e.plan.spec().measure); })
      .def_property_readonly("levels", [](const Ensemble& e) { return array(e.plan.spec().levels); })
      .def_property_readonly("realisations_per_stripe",
                             [](const Ensemble& e) { return e.plan.spec().realisations_per_stripe; })
      .def_property_readonly("uncertain",
                             [](const Ensemble& e) {
                               std::vector<std::string> names;
                               for (const auto& [name, distribution] : e.plan.spec().uncertain) names.push_back(name);
                               return names;
                             })
      .def_property_readonly("model_scale", [](const Ensemble& e) { return e.plan.model_scale(); })
      .def_property_readonly("stability_angle", [](const Ensemble& e) { return e.plan.stability_angle(); })
      .def_property_readonly("time_step", [](const Ensemble& e) { return e.plan.model().time_step; })
      .def_property_readonly("lightest_mass", [](const Ensemble& e) { return e.plan.lightest_mass(); })
      .def_property_readonly("nominal", &nominal_parameters)
      .def_property_readonly("motion_intensities", &motion_intensities)
      .def(
          "intensity_of",
          [](const Ensemble& e, int motion, double scale_factor) {
            if (motion < 0 || motion >= e.plan.motion_count())
              throw py::index_error("no motion " + std::to_string(motion));
            return e.plan.intensity_of(motion, scale_factor);
          },
          py::arg("motion"), py::arg("scale_factor"))
      .def("realisations",
           [](const Ensemble& e) {
             py::dict d;
             for (const auto& [name, values] : plan_columns(e.plan)) d[py::str(name)] = array(values);
             return d;
           })
      .def("__repr__", [](const Ensemble& e) {
        return "<caskdem.Ensemble '" + e.plan.spec().title + "': " + std::to_string(e.plan.size()) + " realisations, " +
               std::to_string(e.plan.motion_count()) + " motions, " + (e.plan.three_d() ? "3D" : "planar") + ">";
      });

  m.def(
      "load_ensemble",
      [](const std::filesystem::path& file) { return std::make_shared<Ensemble>(load_ensemble(file)); },
      py::arg("file"));
  m.def("rollout_parameters", [] {
    py::list out;
    for (const RolloutParameter& p : rollout_parameters()) out.append(py::make_tuple(p.name, p.unit, p.meaning));
    return out;
  });
  py::dict status;
  for (LaneStatus s : {LaneStatus::running, LaneStatus::tipped_over, LaneStatus::left_floor, LaneStatus::slid_off_pad,
                       LaneStatus::non_finite}) {
    status[py::int_(static_cast<int>(s))] = status_name(s);
  }
  m.attr("STATUS") = status;
}

}  // namespace caskdem::python
