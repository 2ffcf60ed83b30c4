// contact: certified collision detection of a linear motion.
#include "common.hpp"
#include "ek/contact/json.hpp"
#include "ek/contact/motion.hpp"

namespace ek::python {

void bind_contact(py::module_& m) {
  m.def(
      "ccd",
      [](const py::handle& start, const py::handle& end, double radius, double separation) {
        MotionCheckOptions opt;
        opt.radius = radius;
        opt.separation = separation;
        const Points x = curve_arg(start, "start"), y = curve_arg(end, "end");
        return result_from_json(motion_check_json(check_linear_motion(x, y, opt)), "ccd");
      },
      py::arg("start"), py::arg("end"), py::kw_only(), py::arg("radius") = MotionCheckOptions{}.radius,
      py::arg("separation") = MotionCheckOptions{}.separation,
      R"doc(Collision detection for the linear motion from start to end ((n, 3) arrays, the same n;
vertex i moves on a line), as `knots ccd`: the largest certified t in [0, 1] such that up
to t no two edges sharing no vertex come closer than separation * min(their start
distance, 2 radius), so the motion up to t cannot change the knot type.

Fields: vertices, t, full_step, separation, dhat, candidates, limiting_edges ([a, b] or
None), clearance_start, clearance_at_t, clearance_end, min_clearance_sampled.)doc");
}

}  // namespace ek::python
