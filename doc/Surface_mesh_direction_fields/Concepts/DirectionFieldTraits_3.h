/*!
\ingroup PkgSurfaceMeshDirectionFieldsConcepts
\cgalConcept

The concept `DirectionFieldTraits_3` describes the types and functors that
`CGAL::Surface_mesh_direction_fields::compute_globally_optimal_directions()`
uses from its geometric traits class. All computations are done in `double`:
the coordinates of the points are read once through `Compute_x_3`,
`Compute_y_3` and `Compute_z_3` and converted with `CGAL::to_double()`, and the
output vectors are built from doubles with `Construct_vector_3`.

\cgalHasModel All the \cgal kernels (for example `CGAL::Simple_cartesian<double>`,
`CGAL::Exact_predicates_inexact_constructions_kernel`,
`CGAL::Exact_predicates_exact_constructions_kernel`).
*/
class DirectionFieldTraits_3
{
public:
  /// \name Types
  /// @{

  /// The number type; it must be constructible from `double`, and `CGAL::to_double()` must accept it.
  typedef unspecified_type FT;

  /// The point type of the vertices.
  typedef unspecified_type Point_3;

  /// The vector type of the output directions (and of the optional vertex normals).
  typedef unspecified_type Vector_3;

  /// Functor with `FT operator()(const Point_3&) const` and `FT operator()(const Vector_3&) const`,
  /// returning the x-coordinate.
  typedef unspecified_type Compute_x_3;

  /// Functor returning the y-coordinate of a `Point_3` or a `Vector_3`.
  typedef unspecified_type Compute_y_3;

  /// Functor returning the z-coordinate of a `Point_3` or a `Vector_3`.
  typedef unspecified_type Compute_z_3;

  /// Functor with `Vector_3 operator()(const FT& x, const FT& y, const FT& z) const`.
  typedef unspecified_type Construct_vector_3;

  /// @}

  /// \name Operations
  /// @{

  /// \return a `Compute_x_3` functor
  Compute_x_3 compute_x_3_object() const;
  /// \return a `Compute_y_3` functor
  Compute_y_3 compute_y_3_object() const;
  /// \return a `Compute_z_3` functor
  Compute_z_3 compute_z_3_object() const;
  /// \return a `Construct_vector_3` functor
  Construct_vector_3 construct_vector_3_object() const;

  /// @}
};
