// Tests of the field readers (io/readers/fields/): MSH $NodeData with a node left out (NaN,
// refused on selection), $ElementData averaged to the nodes, an FRD whose values continue
// on a -2 line and a symmetric tensor's von Mises / principal values.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "io/readers/ReadMesh.h"
#include "io/readers/fields/NodalField.h"
#include "mesher/core/Error.h"

namespace aniso::io {
namespace {

std::string write(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("io_fields_" + name);
  std::ofstream(path) << text;
  return path.string();
}

const char* kTwoTriangles =
    "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndNodes\n"
    "$Elements\n2\n10 2 2 0 1 1 2 3\n20 2 2 0 1 1 3 4\n$EndElements\n";

TEST(IoFields, MshNodeDataAndElementData) {
  const std::string path = write("a.msh", std::string(kTwoTriangles) +
                                              "$NodeData\n1\n\"p\"\n1\n0.0\n3\n0\n1\n3\n1 1.5\n2 2.5\n4 4.5\n$EndNodeData\n"
                                              "$ElementData\n1\n\"e\"\n1\n0.0\n3\n0\n1\n2\n10 1\n20 3\n$EndElementData\n");
  const ReadMesh m = readMesh(path);
  ASSERT_EQ(m.pointData.size(), 1u);
  EXPECT_DOUBLE_EQ(m.pointData[0].values[1], 2.5);
  EXPECT_TRUE(std::isnan(m.pointData[0].values[2]));  // node 3 has no value
  EXPECT_THROW(selectField(m, "p", path), InputError);
  const NodalField e = selectField(m, "E", path);  // the name ignoring case
  EXPECT_DOUBLE_EQ(e.values[0], 2);                // both triangles: (1 + 3) / 2
  EXPECT_DOUBLE_EQ(e.values[1], 1);
  EXPECT_DOUBLE_EQ(e.values[3], 3);
}

TEST(IoFields, FrdContinuationLinesAndTensor) {
  // 4 nodes, one te4; STRESS with its 6 values split 4 + 2 over a -1 and a -2 line
  std::string frd =
      "    1C\n"
      "    2C                             4                                     1\n"
      " -1         1 0.00000E+00 0.00000E+00 0.00000E+00\n"
      " -1         2 1.00000E+00 0.00000E+00 0.00000E+00\n"
      " -1         3 0.00000E+00 1.00000E+00 0.00000E+00\n"
      " -1         4 0.00000E+00 0.00000E+00 1.00000E+00\n"
      " -3\n"
      "    3C                             1                                     1\n"
      " -1         1    3    0    1\n"
      " -2         1         2         3         4\n"
      " -3\n"
      "  100CL  101 1.000000000           4                     0    1           1\n"
      " -4  STRESS      6    1\n"
      " -5  SXX         1    4    1    1\n -5  SYY         1    4    2    2\n -5  SZZ         1    4    3    3\n"
      " -5  SXY         1    4    1    2\n -5  SYZ         1    4    2    3\n -5  SZX         1    4    3    1\n";
  for (int n = 1; n <= 4; ++n)
    frd += " -1         " + std::to_string(n) + " 1.00000E+02-5.00000E+01 0.00000E+00 0.00000E+00\n" +
           " -2           0.00000E+00 3.00000E+01\n";
  frd += " -3\n 9999\n";
  const std::string path = write("a.frd", frd);
  const ReadMesh m = readMesh(path);
  ASSERT_EQ(m.cellCount(), 1u);
  ASSERT_EQ(m.pointData.size(), 1u);
  EXPECT_EQ(m.pointData[0].components, 6);
  const double s[6] = {100, -50, 0, 0, 0, 30};
  EXPECT_NEAR(selectField(m, "STRESS", path).values[2], vonMises(s), 1e-9);
  EXPECT_NEAR(vonMises(s), std::sqrt(0.5 * (150 * 150 + 50 * 50 + 100 * 100) + 3 * 900), 1e-9);
  EXPECT_DOUBLE_EQ(selectField(m, "STRESS:SZX", path).values[0], 30);
  double p[3];
  principalValues(s, p);
  EXPECT_NEAR(selectField(m, "STRESS:p1", path).values[3], p[0], 1e-9);
  EXPECT_GE(p[0], p[1]);
  EXPECT_GE(p[1], p[2]);
  EXPECT_THROW(selectField(m, "STRESS:q", path), InputError);
  EXPECT_THROW(selectField(m, "DISP", path), InputError);
}

}  // namespace
}  // namespace aniso::io
