// Part of test_prescribed_singularities.cpp (one program, one compilation of
// the package): the turns along the surface's loops, and fields given back.
#ifndef SURFACE_MESH_DIRECTION_FIELDS_TEST_PRESCRIBED_SINGULARITIES_LOOPS_H
#define SURFACE_MESH_DIRECTION_FIELDS_TEST_PRESCRIBED_SINGULARITIES_LOOPS_H

static bool closed_loop(const Mesh& mesh, const std::vector<Mesh::Halfedge_index>& loop)
{
  for(std::size_t i = 0; i < loop.size(); ++i)
    if(mesh.target(loop[i]) != mesh.source(loop[(i + 1) % loop.size()])) return false;
  return !loop.empty();
}

// Sum of the field's rotations omega (relative to the transport) along a loop
// of halfedges, in turns of 2 pi: computed from the outputs by the package's
// internals (as the indices are).
static double field_turns_along(const Mesh& mesh, int n, const std::vector<Mesh::Halfedge_index>& loop)
{
  namespace I = SMDF::internal;
  const I::Indexed_mesh m = indexed(mesh);
  const I::Tangent_spaces ts = I::compute_tangent_spaces(m, 1e-6);
  const I::Connection con = I::compute_connection(m, ts, n);
  const std::vector<I::Vec3> normals = I::angle_weighted_vertex_normals(m, ts);
  auto dir = SMDF::internal::find_property_map<Vertex_index, Vector_3>(mesh, "v:direction").value();
  auto angle_at = [&](Vertex_index v) {
    const Vector_3 d = dir[v];
    return std::arg(I::tangent_coefficient(m, ts, std::size_t(v), I::Vec3{d.x(), d.y(), d.z()}, n, normals[std::size_t(v)]));
  };
  double total = 0.;
  for(Mesh::Halfedge_index h : loop)
  {
    // rho of h: from the corner of h's face (or the opposite side, conjugated)
    const bool inside = !mesh.is_border(h);
    const Mesh::Halfedge_index g = inside ? h : mesh.opposite(h);
    const Face_index f = mesh.face(g);
    int c = 0;
    for(Mesh::Halfedge_index k = mesh.halfedge(f); k != g; k = mesh.next(k)) ++c;
    const double rho = std::arg(con.transport[3 * std::size_t(f) + c]) * (inside ? 1. : -1.);
    total += I::reduce_angle(angle_at(mesh.target(h)) - angle_at(mesh.source(h)) - rho);
  }
  return total / (2. * CGAL_PI);
}

static void check_loop_turns(Test_report& report)
{
  Mesh torus;
  make_torus(torus, 1., 0.4, 48, 20);
  torus = with_direction_map(torus);
  auto dir = SMDF::internal::find_property_map<Vertex_index, Vector_3>(torus, "v:direction").value();
  SMDF::Globally_optimal_direction_field<Mesh> field(torus);
  const auto loops = field.prescription_loops();
  report.check(loops.size() == 2 && closed_loop(torus, loops[0]) && closed_loop(torus, loops[1]),
               "torus: two handle loops of halfedges, each closed");
  const Prescription none;
  std::vector<double> turned;
  for(int t : {0, 1, -2})
  {
    std::vector<std::pair<std::size_t, int> > turns = {{0, t}};
    std::vector<std::pair<Face_index, int> > found;
    field.compute(dir, params::degree(4).prescribed_singularities(none).prescribed_loop_turns(turns)
                         .singularities_output_iterator(std::back_inserter(found)));
    turned.push_back(field_turns_along(torus, 4, loops[0]));
    report.check(found.empty(), "torus, loop 0 turned " + std::to_string(t) + " times: no singularity");
  }
  report.check(std::abs(turned[1] - turned[0] - 1.) < 1e-6 && std::abs(turned[2] - turned[0] + 2.) < 1e-6,
               "torus: the field turns along loop 0 as asked (" + std::to_string(turned[0]) + ", " +
                 std::to_string(turned[1]) + ", " + std::to_string(turned[2]) + ")");

  Mesh disk;
  make_disk(disk, 12);
  disk = with_direction_map(disk);
  auto ddir = SMDF::internal::find_property_map<Vertex_index, Vector_3>(disk, "v:direction").value();
  SMDF::Globally_optimal_direction_field<Mesh> disk_field(disk);
  report.check(disk_field.prescription_loops().size() == 1 && closed_loop(disk, disk_field.prescription_loops()[0]),
               "disk: one boundary loop, closed");
  const Prescription center = at_points(disk, {Point_3(0.05, 0.02, 0)}, 1);
  std::vector<std::pair<std::size_t, int> > one = {{0, 1}};
  bool accepted = true, refused = false;
  try { disk_field.compute(ddir, params::degree(4).prescribed_singularities(center).prescribed_loop_turns(one)); }
  catch(const SMDF::Invalid_input_error&) { accepted = false; }
  try { disk_field.compute(ddir, params::degree(4).prescribed_singularities(none).prescribed_loop_turns(one)); }
  catch(const SMDF::Invalid_input_error& e) { refused = std::string(e.what()).find("turns 0 times") != std::string::npos; }
  report.check(accepted && refused, "disk: the free boundary loop accepts only the turns the indices imply");
  std::vector<std::pair<std::size_t, int> > bad = {{3, 1}};
  refused = false;
  try { disk_field.compute(ddir, params::degree(4).prescribed_singularities(none).prescribed_loop_turns(bad)); }
  catch(const SMDF::Invalid_input_error& e) { refused = std::string(e.what()).find("names loop 3") != std::string::npos; }
  report.check(refused, "a loop out of range is refused");

  Mesh cylinder;
  make_cylinder(cylinder, 1., 2., 32, 12);
  cylinder = with_direction_map(cylinder);
  SMDF::Globally_optimal_direction_field<Mesh> cylinder_field(cylinder);
  const auto rims = cylinder_field.prescription_loops();
  auto cdir = SMDF::internal::find_property_map<Vertex_index, Vector_3>(cylinder, "v:direction").value();
  std::vector<std::pair<Face_index, int> > found;
  // the rims have the same length: the first is free; turning the second once turns the first back
  std::vector<std::pair<std::size_t, int> > twist = {{1, 1}, {0, -1}};
  accepted = true;
  try
  {
    cylinder_field.compute(cdir, params::degree(4).prescribed_singularities(none).prescribed_loop_turns(twist)
                                   .singularities_output_iterator(std::back_inserter(found)));
  }
  catch(const SMDF::Invalid_input_error&) { accepted = false; }
  report.check(rims.size() == 2 && closed_loop(cylinder, rims[0]) && closed_loop(cylinder, rims[1]) && accepted &&
                 found.empty(),
               "open cylinder: a twist of one turn between the rims, no singularity");
}

// The smoothest field's singular faces and loop turns, given back.
static void check_round_trip(Test_report& report, const std::string& name, const Mesh& mesh, int n,
                             int& needed_turns, int& refused_without_turns)
{
  auto dir = SMDF::internal::find_property_map<Vertex_index, Vector_3>(mesh, "v:direction").value();
  SMDF::Globally_optimal_direction_field<Mesh> field(mesh);
  Prescription own;
  const SMDF::Direction_field_result smoothest =
    field.compute(dir, params::degree(n).singularities_output_iterator(std::back_inserter(own)));
  std::map<Face_index, int> wanted(own.begin(), own.end());
  Prescription found;
  std::string error;
  SMDF::Direction_field_result back;
  try
  {
    back = field.compute(dir, params::degree(n).prescribed_singularities(own).prescribed_loop_turns(smoothest.loop_turns)
                                .singularities_output_iterator(std::back_inserter(found)));
  }
  catch(const SMDF::Invalid_input_error& e) { error = e.what(); }
  report.check(error.empty() && std::map<Face_index, int>(found.begin(), found.end()) == wanted &&
                 back.loop_turns == smoothest.loop_turns,
               name + ", n = " + std::to_string(n) + ": " + std::to_string(own.size()) + " singular faces and " +
                 std::to_string(smoothest.loop_turns.size()) + " loop turns given back (" + error + ")");
  if(smoothest.loop_turns.empty()) return;
  ++needed_turns;
  try { field.compute(dir, params::degree(n).prescribed_singularities(own)); }
  catch(const SMDF::Invalid_input_error& e)
  {
    ++refused_without_turns;
    report.check(std::string(e.what()).find("loop_turns") != std::string::npos,
                 name + ", n = " + std::to_string(n) + ": the refusal without the turns names them");
  }
}

static void check_round_trips(Test_report& report)
{
  int needed_turns = 0, refused_without_turns = 0;
  for(int holes : {2, 3})
  {
    Mesh slab;
    make_perforated_slab(slab, holes, 3);
    slab = with_direction_map(slab);
    const std::string name = "slab of genus " + std::to_string(holes * holes);
    for(int n : {1, 2, 3, 4, 5, 6, 7, 8, 100}) check_round_trip(report, name, slab, n, needed_turns, refused_without_turns);
  }
  std::cout << "round trips: " << needed_turns << " fields turn other than the nearest choice, "
            << refused_without_turns << " of them refused without their turns" << std::endl;
  report.check(needed_turns > 0, "some smoothest fields turn other than the nearest choice along a loop");

  Mesh torus;
  make_torus(torus, 1., 0.4, 24, 12);
  torus = with_direction_map(torus);
  auto dir = SMDF::internal::find_property_map<Vertex_index, Vector_3>(torus, "v:direction").value();
  std::vector<std::pair<std::size_t, int> > turns = {{0, 1}};
  std::string error;
  try { SMDF::compute_globally_optimal_directions(torus, dir, params::degree(4).prescribed_loop_turns(turns)); }
  catch(const SMDF::Invalid_input_error& e) { error = e.what(); }
  report.check(error.find("prescribed_singularities") != std::string::npos,
               "loop turns without a prescription are refused (" + error + ")");
}

#endif // SURFACE_MESH_DIRECTION_FIELDS_TEST_PRESCRIBED_SINGULARITIES_LOOPS_H
