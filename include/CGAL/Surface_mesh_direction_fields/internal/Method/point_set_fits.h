// Copyright (c) 2026  The Surface_mesh_direction_fields authors.
// All rights reserved.
//
// This file is part of CGAL (www.cgal.org).
//
// $URL$
// $Id$
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s)     : The Surface_mesh_direction_fields authors

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_POINT_SET_FITS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_POINT_SET_FITS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/local_triangulations.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/principal_curvatures.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/quadric_fit.h>
#include <CGAL/Surface_mesh_direction_fields/internal/parallel.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

#include <Eigen/Dense>

#include <cstddef>
#include <vector>

// Local fits of a point set's surface (user manual, "Point Sets"): the
// quadric fit of a mesh vertex (quadric_fit.h), on the point and its nearest
// points instead of a two-ring. It gives the normals (the jet fit of
// CGAL::jet_estimate_normals(), of degree 2, solved by the normal equations
// instead of a singular value decomposition) and the principal curvatures.
// Like the mesh's fit it only samples the surface, so the same surface
// sampled as a mesh or as points gives the same directions.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// The unit normal of the least-squares plane of `sample` (the direction of
// least spread); zero where the points do not span a plane.
inline Vec3 plane_normal(const std::vector<Vec3>& sample)
{
  Vec3 mean{0., 0., 0.};
  for(const Vec3& q : sample) mean = mean + q;
  mean = (1. / static_cast<double>(sample.size())) * mean;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for(const Vec3& q : sample)
  {
    const Eigen::Vector3d r(q[0] - mean[0], q[1] - mean[1], q[2] - mean[2]);
    covariance += r * r.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
  if(eigen.info() != Eigen::Success || !(eigen.eigenvalues()[1] > 0.)) return Vec3{0., 0., 0.};
  const Eigen::Vector3d n = eigen.eigenvectors().col(0);  // eigenvalues in increasing order
  return normalized(Vec3{n[0], n[1], n[2]});
}

// Point i and its `neighbours` nearest points, into `sample` (`nearest`: work space).
inline void nearest_sample(const std::vector<Vec3>& points, const Neighbour_search& search, std::size_t i,
                           std::size_t neighbours, std::vector<std::size_t>& nearest, std::vector<Vec3>& sample)
{
  search.neighbours(i, neighbours, nearest);
  sample.assign(1, points[i]);
  for(std::size_t j : nearest) sample.push_back(points[j]);
}

// The unit normal of every point, unoriented: the normal at the point of a
// quadric fitted to it and its `neighbours` nearest points over their
// least-squares plane (the plane's normal where the quadric is
// undetermined; +z where the points span no plane).
inline std::vector<Vec3> point_set_fitted_normals(const std::vector<Vec3>& points, const Neighbour_search& search,
                                                  std::size_t neighbours)
{
  std::vector<Vec3> normals(points.size(), Vec3{0., 0., 0.});
  parallel_for_each_range(points.size(), [&](std::size_t begin, std::size_t end) {
    std::vector<std::size_t> nearest;
    std::vector<Vec3> sample;
    for(std::size_t i = begin; i < end; ++i)
    {
      nearest_sample(points, search, i, neighbours, nearest, sample);
      const Vec3 plane = plane_normal(sample);
      if(!(norm(plane) > 0.))
      {
        normals[i] = Vec3{0., 0., 1.};  // the points lie on a line (or at one position): no triangle needs it
        continue;
      }
      Vec3 x_axis, y_axis;
      tangent_axes(plane, x_axis, y_axis);
      Jet h;
      normals[i] = fit_quadric(sample, points[i], x_axis, y_axis, plane, h)
                     ? normalized(plane - h[3] * x_axis - h[4] * y_axis)  // (-h_x, -h_y, 1) at the point
                     : plane;
    }
  });
  return normals;
}

// The maximum-curvature vector of every point (length k_max - k_min, in the
// tangent plane of the fitted surface), fitted to the point and its
// `neighbours` nearest points over the plane normal to its normal; zero
// where the fit is degenerate. Which curvature is the larger depends on the
// side the normals point to (outward: a convex bend is positive).
inline std::vector<Vec3> point_set_curvature_vectors(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                                                     const Neighbour_search& search, std::size_t neighbours)
{
  std::vector<Vec3> curvature(points.size(), Vec3{0., 0., 0.});
  parallel_for_each_range(points.size(), [&](std::size_t begin, std::size_t end) {
    std::vector<std::size_t> nearest;
    std::vector<Vec3> sample;
    for(std::size_t i = begin; i < end; ++i)
    {
      nearest_sample(points, search, i, neighbours, nearest, sample);
      Vec3 x_axis, y_axis;
      tangent_axes(normals[i], x_axis, y_axis);
      Jet h;
      if(fit_quadric(sample, points[i], x_axis, y_axis, normals[i], h))
        curvature[i] = maximum_curvature_vector(h, x_axis, y_axis, normals[i]);
    }
  });
  return curvature;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_POINT_SET_FITS_H
