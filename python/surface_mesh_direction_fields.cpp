// The Python module surface_mesh_direction_fields: numpy arrays in, numpy
// arrays out, over the package's C++ API (the class and the free function of
// CGAL/Surface_mesh_direction_fields.h). The options are the named
// parameters of compute_globally_optimal_directions(), in Python's spelling.
#include "python_files.h"
#include "python_point_set.h"

PYBIND11_MODULE(_core, m)
{
  m.doc() = "Globally optimal smooth n-direction fields (vector, line, cross fields) on triangle meshes, after\n"
            "Knoeppel, Crane, Pinkall and Schroeder (2013), from CGAL's Surface_mesh_direction_fields package.";
  m.attr("__version__") = SMDF_VERSION;
  py::register_exception<SMDF::Invalid_input_error>(m, "InvalidInputError", PyExc_ValueError);
  py::register_exception<SMDF::Solver_failure_error>(m, "SolverFailureError", PyExc_RuntimeError);
  py::register_exception<SMDF::Computation_interrupted>(m, "ComputationInterrupted", PyExc_RuntimeError);
  bind_result(m);
  bind_field(m);
  bind_face_field(m);
  bind_point_set_field(m);
  bind_files(m);
  m.def("set_openblas_thread_control", &SMDF::set_openblas_thread_control, py::arg("enabled"),
        "Lets the factorization set OpenBLAS's process-wide number of threads to one while its own threads\n"
        "factor side by side (4 to 11% faster). On by default in this module, as in the command-line program,\n"
        "so that both give the same field to the last digit; meanwhile another thread's call into the same\n"
        "OpenBLAS (numpy's, with Debian's numpy) runs on one thread. set_openblas_thread_control(False) leaves\n"
        "OpenBLAS alone (the C++ library's default); the fields then differ in the last digits (about 1e-10).");
  // the module is a front end, as the program is: the same setting, the same digits
  SMDF::set_openblas_thread_control(true);
  m.def("openblas_thread_control", &SMDF::openblas_thread_control,
        "Whether the factorization sets OpenBLAS's number of threads (see set_openblas_thread_control).");
}
