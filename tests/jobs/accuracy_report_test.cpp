// The accuracy report (src/jobs/accuracy_report.hpp): which methods the long-time energy plot
// runs, decided by the list the report measures and not by its length.
#include "jobs/accuracy_report.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace bookspin::jobs {
namespace {

using analysis::Method;
using physics::Integrator;
using physics::ModelKind;

std::vector<std::string> names(const std::vector<Method>& methods) {
  std::vector<std::string> out;
  for (const Method& m : methods)
    out.push_back(std::string(physics::to_string(m.kind)) + ":" +
                  std::string(physics::to_string(m.integrator)));
  return out;
}

TEST(AccuracyReport, EveryMethodRunsTheRigidPairsOverTheLongTime) {
  // The rigid pairs: rigid-matrix and rigid-quaternion × the five rigid integrators
  // (docs/physics.md §10), written out here.
  std::vector<std::string> rigid;
  for (const char* kind : {"rigid-matrix", "rigid-quaternion"})
    for (const char* integrator : {"euler", "rk4", "implicit-midpoint", "splitting", "splitting4"})
      rigid.push_back(std::string(kind) + ":" + integrator);
  EXPECT_EQ(names(long_time_methods(analysis::accuracy_methods())), rigid);
}

TEST(AccuracyReport, AChosenListRunsItsMethodsButTheParticleModels) {
  const std::vector<Method> chosen{{ModelKind::particle, Integrator::euler},
                                   {ModelKind::rigid_quaternion, Integrator::rk4},
                                   {ModelKind::mujoco, Integrator::rk4}};
  EXPECT_EQ(names(long_time_methods(chosen)),
            (std::vector<std::string>{"rigid-quaternion:rk4", "mujoco:rk4"}));
  EXPECT_TRUE(long_time_methods({{ModelKind::particle, Integrator::euler}}).empty());

  // As many methods as every method, but not every method: the list itself, no particles.
  std::vector<Method> as_many = analysis::accuracy_methods();
  as_many.front() = {ModelKind::bullet, Integrator::none};
  std::vector<std::string> expected;
  for (const Method& m : as_many)
    if (m.kind != ModelKind::particle) expected.push_back(names({m}).front());
  EXPECT_EQ(names(long_time_methods(as_many)), expected);
  EXPECT_NE(names(long_time_methods(as_many)), names(analysis::rigid_methods()));
}

}  // namespace
}  // namespace bookspin::jobs
