// The optional named parameters that the program and the Python module pass
// only where their user gave the option (guidance, lambda_t or
// alignment_weight, constraints, feature edges, prescribed singularities; for
// point sets the guidance and its lambda_t or alignment_weight).
// Named parameters are types, so each option present or absent is a branch
// taken at run time: each step below adds its parameter when it is given and
// hands the parameters on to the next step; the last calls `compute(np)` (the
// free function or the class's compute()). An option a front end does not
// offer keeps the type `Not_offered`, and its step is compiled out.
#ifndef SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_OPTIONAL_NAMED_PARAMETERS_H
#define SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_OPTIONAL_NAMED_PARAMETERS_H

#include <cstddef>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace optional_named_parameters {

struct Not_offered
{};

// The options given, as the maps and ranges the named parameters take.
// ConstraintMaps: a pair (vertex_is_constrained_map, vertex_constrained_direction_map).
template <typename Face, typename GuidanceMap, typename FeatureMap, typename ConstraintMaps = Not_offered>
struct Given_options
{
  std::optional<double> alignment_weight, alignment_lambda;  // at most one
  std::optional<GuidanceMap> guidance;
  std::optional<ConstraintMaps> constraints;
  std::optional<FeatureMap> features;
  const std::vector<std::pair<Face, int> >* prescribed = nullptr;
  const std::vector<std::pair<std::size_t, int> >* loop_turns = nullptr;  // with `prescribed`; null: none
};

template <typename Options, typename NP, typename Compute>
auto with_prescription(const Options& o, const NP& np, const Compute& compute)
{
  static const std::vector<std::pair<std::size_t, int> > no_turns;
  if(o.prescribed)  // an empty list of loop turns is the default: 0 for every loop
    return compute(np.prescribed_singularities(*o.prescribed).prescribed_loop_turns(o.loop_turns ? *o.loop_turns : no_turns));
  return compute(np);
}

template <typename Options, typename NP, typename Compute>
auto with_features(const Options& o, const NP& np, const Compute& compute)
{
  if(o.features) return with_prescription(o, np.edge_is_feature_map(*o.features), compute);
  return with_prescription(o, np, compute);
}

template <typename Options, typename NP, typename Compute>
auto with_constraints(const Options& o, const NP& np, const Compute& compute)
{
  if constexpr(!std::is_same<typename decltype(o.constraints)::value_type, Not_offered>::value)
  {
    if(o.constraints)
      return with_features(o, np.vertex_is_constrained_map(o.constraints->first)
                                .vertex_constrained_direction_map(o.constraints->second), compute);
  }
  return with_features(o, np, compute);
}

template <typename Options, typename NP, typename Compute>
auto with_alignment(const Options& o, const NP& np, const Compute& compute)
{
  if(o.alignment_weight) return with_constraints(o, np.alignment_weight(*o.alignment_weight), compute);
  if(o.alignment_lambda) return with_constraints(o, np.alignment_lambda(*o.alignment_lambda), compute);
  return with_constraints(o, np, compute);
}

// compute(np + the named parameters of the options given in `o`), for meshes
template <typename Options, typename NP, typename Compute>
auto compute_with(const Options& o, const NP& np, const Compute& compute)
{
  if(o.guidance) return with_alignment(o, np.vertex_guidance_map(*o.guidance), compute);
  return with_alignment(o, np, compute);
}

template <typename Options, typename NP, typename Compute>
auto with_point_alignment(const Options& o, const NP& np, const Compute& compute)
{
  if(o.alignment_weight) return compute(np.alignment_weight(*o.alignment_weight));
  if(o.alignment_lambda) return compute(np.alignment_lambda(*o.alignment_lambda));
  return compute(np);
}

// The same for point sets: point_guidance_map, and alignment_weight or
// alignment_lambda (which also apply to the curvature alignment).
template <typename Options, typename NP, typename Compute>
auto compute_with_point_guidance(const Options& o, const NP& np, const Compute& compute)
{
  if(o.guidance) return with_point_alignment(o, np.point_guidance_map(*o.guidance), compute);
  return with_point_alignment(o, np, compute);
}

}  // namespace optional_named_parameters

#endif // SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_OPTIONAL_NAMED_PARAMETERS_H
