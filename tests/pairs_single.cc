// Contact > Type = pairs with one two-body pair is Type = two bodies
// (issue 51): prm/hertz_two_cylinders.prm (2D) and prm/hertz_two_spheres.prm
// (3D) run as committed and again with their pair declared as
// 'Two-body pairs = 0:10' and their Hertz reference as 'Pair 1 > Hertz
// reference'. The pair's penalty scale is 1, so the runs must take the same
// Newton iterations and give the same energy, force on body 1, a, p0 and
// pressure L2 error (pair1_...) to 1e-12 relative (measured: identical to
// the last digit), and the same contact area with the same reference;
// the E* of the pair, computed from its two bodies, gives
// the same reference. The pairs scene's own resultant (every contact force
// on every body) is the pair's action plus reaction: 0 within 1e-8 of the
// force.

#include "run_output.h"

#include <cmath>
#include <fstream>
#include <string>

namespace
{
  using RunOutput::summary_quantity;
  using RunOutput::verdict;

  void
  check(std::ostream      &out,
        const std::string &name,
        const std::string &scene,
        const std::string &hertz)
  {
    const std::string pairs = "subsection Contact\n  set Type = pairs\n"
                              "  subsection Hertz reference\n    set " +
                              hertz +
                              " = 0\n  end\n"
                              "  subsection Pairs\n    set Two-body pairs = 0:10\n"
                              "    subsection Pair 1\n      subsection Hertz reference\n"
                              "        include " +
                              name + "_hertz.prm\n      end\n    end\n  end\nend\n";
    // The scene's own Hertz subsection, copied into Pair 1.
    {
      std::ifstream     in(std::string(SIGNORINI_SOURCE_DIR) + "/prm/" + scene);
      std::ofstream     copy(name + "_hertz.prm");
      std::string       line;
      bool              inside = false;
      while (std::getline(in, line))
        {
          if (line.find("subsection Hertz reference") != std::string::npos)
            inside = true;
          else if (inside && line.find("  end") == 0)
            inside = false;
          else if (inside)
            copy << line << "\n";
        }
    }
    const bool ran = RunOutput::run_scene(name + "_two_bodies", scene, "") == 0 &&
                     RunOutput::run_scene(name + "_pairs", scene, pairs) == 0;
    out << name << ": both runs exit 0: " << verdict(ran) << "\n";
    const std::string a = name + "_two_bodies/summary.json",
                      b = name + "_pairs/summary.json";
    const auto same = [](const double x, const double y) {
      return (std::isnan(x) && std::isnan(y)) || // neither has a reference
             std::abs(x - y) <= 1e-12 * std::max(std::abs(x), std::abs(y));
    };
    bool        all  = RunOutput::newton_iterations(name + "_two_bodies") ==
                     RunOutput::newton_iterations(name + "_pairs");
    const char *force = scene.find("spheres") != std::string::npos ? "z" : "y";
    for (const std::string q : {std::string("hertz_a"), std::string("hertz_p0"),
                                std::string("hertz_pressure_l2_error"),
                                std::string("contact_area"),
                                std::string("contact_force_") + force})
      {
        all = all && same(summary_quantity(a, q), summary_quantity(b, "pair1_" + q)) &&
              same(summary_quantity(a, q, "reference"),
                   summary_quantity(b, "pair1_" + q, "reference"));
        std::cerr << name << " " << q << " " << summary_quantity(a, q) << " "
                  << summary_quantity(b, "pair1_" + q) << "\n";
      }
    all = all && same(summary_quantity(a, "potential_energy"),
                      summary_quantity(b, "potential_energy"));
    out << name << ": the same iterations, energy, force, area, a, p0, L2 error (1e-12): "
        << verdict(all) << "\n";
    const double total = summary_quantity(b, std::string("contact_force_") + force);
    const double pair  = summary_quantity(b, std::string("pair1_contact_force_") + force);
    out << name << ": the pairs scene's resultant is action + reaction = 0 (1e-8): "
        << verdict(std::abs(total) <= 1e-8 * std::abs(pair)) << "\n";
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  check(out, "cylinders", "hertz_two_cylinders.prm", "Line load");
  check(out, "spheres", "hertz_two_spheres.prm", "Point load");
}
