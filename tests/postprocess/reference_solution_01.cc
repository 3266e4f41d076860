// Reference solutions. Soil column (thesis Table 4.5): the closed form
// used for errors equals the corrected series of eq. 4.6, is zero at
// t = 0, vanishes at the fixed bottom and has zero stress at the free
// top. The 1D updated Lagrangian FEM reference reproduces the analytic
// small-deformation bar and column, converging as the mesh is refined.
#include <deal.II/base/parameter_handler.h>

#include <psmpm/material/material.h>
#include <psmpm/postprocess/reference.h>
#include <psmpm/postprocess/references/soil_column.h>
#include <psmpm/postprocess/updated_lagrangian_1d.h>

#include "../tests.h"

using namespace psmpm;

std::unique_ptr<Postprocess::Reference<2>>
make_reference(const std::string &type,
               const double       rho,
               const double       E,
               const double       L,
               const double       H,
               const double       g,
               const unsigned int n  = 2000,
               const double       v0 = 0.1)
{
  ParameterHandler prm;
  Material::Material<2>::declare_parameters(prm);
  Postprocess::Reference<2>::declare_parameters(prm);
  prm.enter_subsection("Reference solution");
  prm.set("Type", type);
  prm.set("ULFEM elements", std::to_string(n));
  prm.set("Velocity amplitude", std::to_string(v0));
  prm.leave_subsection();
  prm.enter_subsection("Material");
  prm.set("Density", std::to_string(rho));
  prm.set("Young's modulus", std::to_string(E));
  prm.set("Poisson's ratio", "0");
  prm.leave_subsection();
  const auto material = Material::Material<2>::create(prm);
  return Postprocess::Reference<2>::create(prm,
                                           *material,
                                           L,
                                           H,
                                           Tensor<1, 2>({0, -g}));
}

int
main()
{
  std::ofstream out("output");
  const double  H = 25, rho = 1, E = 5e4, g = 9.81;
  auto          column = make_reference("soil column", rho, E, 2, H, g);

  double closed_vs_series = 0, at_zero = 0, bottom = 0, top_stress = 0,
         scale = 0;
  for (const double t : {0., 0.01, 0.05, 0.13, 0.3, 0.5})
    {
      for (unsigned int i = 0; i <= 50; ++i)
        {
          const double y = H * i / 50.;
          const double u = column->evaluate(Point<2>(1, y), t).displacement[1];
          closed_vs_series = std::max(
            closed_vs_series,
            std::abs(
              u - Postprocess::soil_column_series(rho, E, g, H, y, t, 4000)));
          scale = std::max(scale, std::abs(u));
          if (t == 0)
            at_zero = std::max(at_zero, std::abs(u));
        }
      bottom =
        std::max(bottom,
                 std::abs(column->evaluate(Point<2>(1, 0), t).displacement[1]));
      top_stress =
        std::max(top_stress,
                 std::abs(column->evaluate(Point<2>(1, H), t).stress[1][1]));
    }
  out << "column: largest |u| / (rho g H^2 / E) = " << std::setprecision(4)
      << scale / (rho * g * H * H / E) << std::endl;
  PSMPM_CHECK(out, closed_vs_series < 1e-9 * scale);
  PSMPM_CHECK(out, at_zero < 1e-14 * scale);
  PSMPM_CHECK(out, bottom < 1e-14 * scale);
  PSMPM_CHECK(out, top_stress < 1e-12 * rho * g * H);
  // Static limit of the mean: the time average of u is u_static; at
  // t = 2H/c (half a period) the column is at twice its static sag.
  const double c = std::sqrt(E / rho);
  const double sag =
    column->evaluate(Point<2>(1, H), 2 * H / c).displacement[1];
  PSMPM_CHECK(out,
              std::abs(sag - (-rho * g * H * H / E)) <
                1e-12 * rho * g * H * H / E);

  // ULFEM against the analytic small-deformation solutions: errors shrink
  // by about 4 when the elements are halved (second order).
  for (const std::string which : {"bar", "column"})
    {
      double err[2];
      for (unsigned int level = 0; level < 2; ++level)
        {
          const unsigned int n = 200 << level;
          // Small deformation: bar strain 1e-7, column strain ~ 5e-3.
          auto exact =
            which == "bar" ?
              make_reference("vibrating bar", 1, 100, 25, 2, 0, 2, 1e-6) :
              make_reference("soil column", rho, E, 2, H, g);
          auto ulfem =
            which == "bar" ?
              make_reference("vibrating bar ulfem", 1, 100, 25, 2, 0, n, 1e-6) :
              make_reference("soil column ulfem", rho, E, 2, H, g, n);
          const double t = which == "bar" ? 2.0 : 0.07;
          ulfem->advance_to(t);
          double e = 0, s = 0;
          for (unsigned int i = 0; i <= 100; ++i)
            {
              const Point<2> X = which == "bar" ? Point<2>(25 * i / 100., 1) :
                                                  Point<2>(1, H * i / 100.);
              const unsigned int d = which == "bar" ? 0 : 1;
              e                    = std::max(e,
                           std::abs(ulfem->evaluate(X, t).displacement[d] -
                                    exact->evaluate(X, t).displacement[d]));
              s = std::max(s, std::abs(exact->evaluate(X, t).displacement[d]));
            }
          err[level] = e / s;
        }
      out << which << ": ULFEM relative errors " << std::setprecision(2)
          << err[0] << ", " << err[1] << std::endl;
      PSMPM_CHECK(out, err[1] < 2e-3);
      PSMPM_CHECK(out, err[0] / err[1] > 1.8);
    }
}
