#pragma once
// Small STEP texts written for the tests (no third-party file): stepWithContext wraps the
// entities of a shape into a file; unitCubeStep is a unit cube of six planar faces, its boundary given as `shellKind` (CLOSED_SHELL, or OPEN_SHELL for the defect a
// writer makes) under a MANIFOLD_SOLID_BREP, in millimetres, the solid an item of a
// `representation` (OCCT transfers a solid over an open shell as a solid from an
// ADVANCED_BREP_SHAPE_REPRESENTATION, as faces only from a
// MANIFOLD_SURFACE_SHAPE_REPRESENTATION).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace aniso::test {

/// A STEP file of one part in millimetres: the header, the product and its geometric
/// context (#1 to #12; #7 the product definition shape, #12 the context) around `data`, the
/// entities from #20 on that give the shape.
inline std::string stepWithContext(const std::string& data) {
  return R"(ISO-10303-21;
HEADER;
FILE_DESCRIPTION(('anisomesh test model'),'2;1');
FILE_NAME('test.stp','2026-01-01T00:00:00',(''),(''),'anisomesh tests','','');
FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));
ENDSEC;
DATA;
#1=APPLICATION_CONTEXT('automotive_design');
#2=PRODUCT_CONTEXT('',#1,'mechanical');
#3=PRODUCT('part','part','',(#2));
#4=PRODUCT_DEFINITION_FORMATION('','',#3);
#5=PRODUCT_DEFINITION_CONTEXT('part definition',#1,'design');
#6=PRODUCT_DEFINITION('','',#4,#5);
#7=PRODUCT_DEFINITION_SHAPE('','',#6);
#8=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.));
#9=(NAMED_UNIT(*)PLANE_ANGLE_UNIT()SI_UNIT($,.RADIAN.));
#10=(NAMED_UNIT(*)SI_UNIT($,.STERADIAN.)SOLID_ANGLE_UNIT());
#11=UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.0E-7),#8,'distance_accuracy_value','');
#12=(GEOMETRIC_REPRESENTATION_CONTEXT(3)GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((#11))GLOBAL_UNIT_ASSIGNED_CONTEXT((#8,#9,#10))REPRESENTATION_CONTEXT('','3D'));
)" + data + "ENDSEC;\nEND-ISO-10303-21;\n";
}

inline std::string unitCubeStep(const std::string& shellKind,
                                const std::string& representation = "ADVANCED_BREP_SHAPE_REPRESENTATION") {
  std::string s = stepWithContext(R"(#20=CARTESIAN_POINT('',(0.,0.,0.));
#21=CARTESIAN_POINT('',(1.,0.,0.));
#22=CARTESIAN_POINT('',(1.,1.,0.));
#23=CARTESIAN_POINT('',(0.,1.,0.));
#24=CARTESIAN_POINT('',(0.,0.,1.));
#25=CARTESIAN_POINT('',(1.,0.,1.));
#26=CARTESIAN_POINT('',(1.,1.,1.));
#27=CARTESIAN_POINT('',(0.,1.,1.));
#30=VERTEX_POINT('',#20);
#31=VERTEX_POINT('',#21);
#32=VERTEX_POINT('',#22);
#33=VERTEX_POINT('',#23);
#34=VERTEX_POINT('',#24);
#35=VERTEX_POINT('',#25);
#36=VERTEX_POINT('',#26);
#37=VERTEX_POINT('',#27);
#40=DIRECTION('',(1.,0.,0.));
#41=DIRECTION('',(0.,1.,0.));
#42=DIRECTION('',(0.,0.,1.));
#43=DIRECTION('',(-1.,0.,0.));
#44=DIRECTION('',(0.,-1.,0.));
#45=DIRECTION('',(0.,0.,-1.));
#46=VECTOR('',#40,1.);
#47=VECTOR('',#41,1.);
#48=VECTOR('',#42,1.);
#50=EDGE_CURVE('',#30,#31,#60,.T.);
#51=EDGE_CURVE('',#31,#32,#61,.T.);
#52=EDGE_CURVE('',#33,#32,#62,.T.);
#53=EDGE_CURVE('',#30,#33,#63,.T.);
#54=EDGE_CURVE('',#34,#35,#64,.T.);
#55=EDGE_CURVE('',#35,#36,#65,.T.);
#56=EDGE_CURVE('',#37,#36,#66,.T.);
#57=EDGE_CURVE('',#34,#37,#67,.T.);
#58=EDGE_CURVE('',#30,#34,#68,.T.);
#59=EDGE_CURVE('',#31,#35,#69,.T.);
#70=EDGE_CURVE('',#32,#36,#71,.T.);
#72=EDGE_CURVE('',#33,#37,#73,.T.);
#60=LINE('',#20,#46);
#61=LINE('',#21,#47);
#62=LINE('',#23,#46);
#63=LINE('',#20,#47);
#64=LINE('',#24,#46);
#65=LINE('',#25,#47);
#66=LINE('',#27,#46);
#67=LINE('',#24,#47);
#68=LINE('',#20,#48);
#69=LINE('',#21,#48);
#71=LINE('',#22,#48);
#73=LINE('',#23,#48);
#100=PLANE('',#101);
#101=AXIS2_PLACEMENT_3D('',#20,#45,#40);
#102=ADVANCED_FACE('bottom',(#103),#100,.T.);
#103=FACE_OUTER_BOUND('',#104,.T.);
#104=EDGE_LOOP('',(#105,#106,#107,#108));
#105=ORIENTED_EDGE('',*,*,#53,.T.);
#106=ORIENTED_EDGE('',*,*,#52,.T.);
#107=ORIENTED_EDGE('',*,*,#51,.F.);
#108=ORIENTED_EDGE('',*,*,#50,.F.);
#110=PLANE('',#111);
#111=AXIS2_PLACEMENT_3D('',#24,#42,#40);
#112=ADVANCED_FACE('top',(#113),#110,.T.);
#113=FACE_OUTER_BOUND('',#114,.T.);
#114=EDGE_LOOP('',(#115,#116,#117,#118));
#115=ORIENTED_EDGE('',*,*,#54,.T.);
#116=ORIENTED_EDGE('',*,*,#55,.T.);
#117=ORIENTED_EDGE('',*,*,#56,.F.);
#118=ORIENTED_EDGE('',*,*,#57,.F.);
#120=PLANE('',#121);
#121=AXIS2_PLACEMENT_3D('',#20,#44,#40);
#122=ADVANCED_FACE('front',(#123),#120,.T.);
#123=FACE_OUTER_BOUND('',#124,.T.);
#124=EDGE_LOOP('',(#125,#126,#127,#128));
#125=ORIENTED_EDGE('',*,*,#50,.T.);
#126=ORIENTED_EDGE('',*,*,#59,.T.);
#127=ORIENTED_EDGE('',*,*,#54,.F.);
#128=ORIENTED_EDGE('',*,*,#58,.F.);
#130=PLANE('',#131);
#131=AXIS2_PLACEMENT_3D('',#23,#41,#40);
#132=ADVANCED_FACE('back',(#133),#130,.T.);
#133=FACE_OUTER_BOUND('',#134,.T.);
#134=EDGE_LOOP('',(#135,#136,#137,#138));
#135=ORIENTED_EDGE('',*,*,#72,.T.);
#136=ORIENTED_EDGE('',*,*,#56,.T.);
#137=ORIENTED_EDGE('',*,*,#70,.F.);
#138=ORIENTED_EDGE('',*,*,#52,.F.);
#140=PLANE('',#141);
#141=AXIS2_PLACEMENT_3D('',#20,#43,#41);
#142=ADVANCED_FACE('left',(#143),#140,.T.);
#143=FACE_OUTER_BOUND('',#144,.T.);
#144=EDGE_LOOP('',(#145,#146,#147,#148));
#145=ORIENTED_EDGE('',*,*,#58,.T.);
#146=ORIENTED_EDGE('',*,*,#57,.T.);
#147=ORIENTED_EDGE('',*,*,#72,.F.);
#148=ORIENTED_EDGE('',*,*,#53,.F.);
#150=PLANE('',#151);
#151=AXIS2_PLACEMENT_3D('',#21,#40,#41);
#152=ADVANCED_FACE('right',(#153),#150,.T.);
#153=FACE_OUTER_BOUND('',#154,.T.);
#154=EDGE_LOOP('',(#155,#156,#157,#158));
#155=ORIENTED_EDGE('',*,*,#51,.T.);
#156=ORIENTED_EDGE('',*,*,#70,.T.);
#157=ORIENTED_EDGE('',*,*,#55,.F.);
#158=ORIENTED_EDGE('',*,*,#59,.F.);
#200=SHELL_KIND('',(#102,#112,#122,#132,#142,#152));
#201=MANIFOLD_SOLID_BREP('cube',#200);
#202=REPRESENTATION_KIND('',(#201),#12);
#203=SHAPE_DEFINITION_REPRESENTATION(#7,#202);
)");
  s.replace(s.find("SHELL_KIND"), 10, shellKind);
  s.replace(s.find("REPRESENTATION_KIND"), 19, representation);
  return s;
}

/// Writes `text` to a file of that name in the temporary directory; returns its path.
inline std::string writeTempStep(const std::string& name, const std::string& text) {
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  std::ofstream(path) << text;
  return path;
}

}  // namespace aniso::test
