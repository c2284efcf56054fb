// A client of direction_field's files, written as QuadWild reads them: the
// mesh (--mesh-out) with vcglib's importer, the cross field (--rosy) with
// ImporterFIELD::Load4ROSY, then CrossField::OrientDirectionFaceCoherently and
// CrossField::UpdateSingularByCross. Prints "v missmatch" per singular
// interior vertex (vcglib's own rule on the boundary is left out), and with a
// .sharp file the edges it marks as "sharp a b type" (vertex indices).
//
//   usage: vcglib_field_reader MESH ROSY [SHARP]
// Compiled by the tests against ../shared/clients/vcglib (never shipped).

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/flag.h>
#include <vcg/complex/algorithms/parametrization/tangent_field_operators.h>
#include <wrap/io_trimesh/import_obj.h>
#include <wrap/io_trimesh/import_off.h>
#include <wrap/io_trimesh/import_field.h>

#include <cstdio>
#include <iostream>

class Vertex;
class Face;
struct Types : public vcg::UsedTypes<vcg::Use<Vertex>::AsVertexType, vcg::Use<Face>::AsFaceType>
{};
class Vertex : public vcg::Vertex<Types, vcg::vertex::Coord3d, vcg::vertex::Normal3d, vcg::vertex::BitFlags,
                                  vcg::vertex::VFAdj, vcg::vertex::CurvatureDird, vcg::vertex::Qualityd>
{};
class Face : public vcg::Face<Types, vcg::face::VertexRef, vcg::face::Normal3d, vcg::face::BitFlags, vcg::face::FFAdj,
                              vcg::face::VFAdj, vcg::face::CurvatureDird, vcg::face::Qualityd, vcg::face::Mark>
{};
class Mesh : public vcg::tri::TriMesh<std::vector<Vertex>, std::vector<Face> >
{};

int main(int argc, char** argv)
{
  if(argc < 3) { std::cerr << "usage: vcglib_field_reader MESH ROSY [SHARP]\n"; return 2; }
  Mesh mesh;
  // QuadWild reads OBJ (its _rem.obj); OFF as well here
  const std::string path = argv[1];
  int mask = 0;
  const bool obj = path.size() > 4 && path.compare(path.size() - 4, 4, ".obj") == 0;
  const int error = obj ? vcg::tri::io::ImporterOBJ<Mesh>::Open(mesh, argv[1], mask)
                        : vcg::tri::io::ImporterOFF<Mesh>::Open(mesh, argv[1]);
  if(error != 0 && !(obj && !vcg::tri::io::ImporterOBJ<Mesh>::ErrorCritical(error)))
  { std::cerr << "cannot read " << argv[1] << "\n"; return 1; }
  vcg::tri::UpdateTopology<Mesh>::FaceFace(mesh);
  vcg::tri::UpdateTopology<Mesh>::VertexFace(mesh);
  vcg::tri::UpdateNormal<Mesh>::PerFaceNormalized(mesh);
  vcg::tri::UpdateFlags<Mesh>::FaceBorderFromFF(mesh);
  vcg::tri::UpdateFlags<Mesh>::VertexBorderFromFaceAdj(mesh);
  if(!vcg::tri::io::ImporterFIELD<Mesh>::Load4ROSY(mesh, argv[2])) { std::cerr << "cannot read " << argv[2] << "\n"; return 1; }
  vcg::tri::CrossField<Mesh>::OrientDirectionFaceCoherently(mesh);
  vcg::tri::CrossField<Mesh>::UpdateSingularByCross(mesh, false);
  auto singular = vcg::tri::Allocator<Mesh>::GetPerVertexAttribute<bool>(mesh, std::string("Singular"));
  auto index = vcg::tri::Allocator<Mesh>::GetPerVertexAttribute<int>(mesh, std::string("SingularIndex"));
  for(std::size_t v = 0; v < mesh.vert.size(); ++v)
    if(singular[v]) std::cout << v << " " << index[v] << "\n";
  if(argc > 3)
  {
    // QuadWild's LoadSharpFeatures: the count, then "type,face,edge" lines
    FILE* f = std::fopen(argv[3], "rt");
    if(!f) { std::cerr << "cannot read " << argv[3] << "\n"; return 1; }
    int count = 0;
    if(std::fscanf(f, "%d\n", &count) != 1) return 1;
    for(int i = 0; i < count; ++i)
    {
      int type = 0, face = 0, edge = 0;
      if(std::fscanf(f, "%d,%d,%d\n", &type, &face, &edge) != 3 || face < 0 || face >= int(mesh.face.size()) ||
         edge < 0 || edge > 2)
      { std::cerr << "bad sharp line " << i << "\n"; return 1; }
      const Face& t = mesh.face[face];
      std::cout << "sharp " << vcg::tri::Index(mesh, t.cV0(edge)) << " " << vcg::tri::Index(mesh, t.cV1(edge)) << " "
                << type << "\n";
    }
    std::fclose(f);
  }
  return 0;
}
