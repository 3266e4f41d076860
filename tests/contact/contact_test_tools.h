// ---------------------------------------------------------------------
// psmpm: what the contact tests share: a Contact made from entries of
// subsection Contact, 2D vectors, and the node's momentum and kinetic
// energy.
// ---------------------------------------------------------------------
#ifndef psmpm_tests_contact_test_tools_h
#define psmpm_tests_contact_test_tools_h

#include <deal.II/base/parameter_handler.h>

#include <psmpm/simulator/contact.h>

#include <string>
#include <utility>
#include <vector>

using psmpm::Simulator::Contact;
using psmpm::Simulator::ContactFields;
using psmpm::Simulator::ContactPairStatistics;

/// A Contact with the entries @p settings of subsection Contact, parsed
/// and checked against @p n_bodies bodies.
template <int dim>
Contact<dim>
make_contact(const std::vector<std::pair<std::string, std::string>> &settings,
             const unsigned int                                      n_bodies)
{
  dealii::ParameterHandler prm;
  prm.enter_subsection("Contact");
  Contact<dim>::declare_parameters(prm);
  for (const auto &[entry, value] : settings)
    prm.set(entry, value);
  Contact<dim> contact;
  contact.parse_parameters(prm);
  prm.leave_subsection();
  contact.check_bodies(n_bodies);
  return contact;
}

/// The 2D vector (x, y).
inline dealii::Tensor<1, 2>
vec(const double x, const double y)
{
  dealii::Tensor<1, 2> t;
  t[0] = x;
  t[1] = y;
  return t;
}

/// sum_b m_b v_b at node @p i.
template <int dim>
dealii::Tensor<1, dim>
node_momentum(const ContactFields<dim> &f, const unsigned int i)
{
  dealii::Tensor<1, dim> p;
  for (unsigned int b = 0; b < f.n_bodies; ++b)
    p += f.mass[i * f.n_bodies + b] * f.velocity[i * f.n_bodies + b];
  return p;
}

/// sum_b m_b |v_b|^2 / 2 at node @p i.
template <int dim>
double
node_kinetic_energy(const ContactFields<dim> &f, const unsigned int i)
{
  double e = 0;
  for (unsigned int b = 0; b < f.n_bodies; ++b)
    e += 0.5 * f.mass[i * f.n_bodies + b] *
         f.velocity[i * f.n_bodies + b].norm_square();
  return e;
}

/// sum_b m_b |v_b| at node @p i: the scale of its momentum round-off.
template <int dim>
double
node_momentum_scale(const ContactFields<dim> &f, const unsigned int i)
{
  double s = 0;
  for (unsigned int b = 0; b < f.n_bodies; ++b)
    s += f.mass[i * f.n_bodies + b] * f.velocity[i * f.n_bodies + b].norm();
  return s;
}

#endif
