// The `tribo._core` extension, the compiled part of the `tribo` package (python/tribo/
// re-exports it): its entry point (python/bindings.hpp lists the parts).
#include "python/bindings.hpp"

PYBIND11_MODULE(_core, m) {
  m.doc() =
      "Tribo: rigid multibody dynamics with swappable friction laws (docs/python.md).\n"
      "load_scene/load_urdf -> Scene; Scene.run -> Result (trajectory as NumPy arrays, summary "
      "as a dict); Simulator for step-by-step control; friction_law for the laws' mu(v); sweep "
      "and modes for studies.";
  m.attr("__version__") = TRIBO_VERSION;  // the CMake project's version (python/CMakeLists.txt)
  tribo::python::bindErrors(m);
  tribo::python::bindFriction(m);
  tribo::python::bindScene(m);
  tribo::python::bindSimulator(m);
  tribo::python::bindControl(m);
  tribo::python::bindStudies(m);
  tribo::python::bindSweep(m);
}
