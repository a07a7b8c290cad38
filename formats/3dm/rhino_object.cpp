#include "formats/3dm/rhino_object.hpp"

#include <algorithm>
#include <array>

#include "formats/3dm/curve_objects.hpp"
#include "formats/3dm/mesh_object.hpp"
#include "formats/3dm/surface_objects.hpp"
#include "formats/3dm/typecodes.hpp"

namespace cadnurbs::rhino {
namespace {

using ClassReader = RhinoGeometry (*)(ArchiveReader&);

// Adapts a reader returning one geometry type to the table's signature.
template <auto read>
RhinoGeometry as_geometry(ArchiveReader& reader) {
  return RhinoGeometry(read(reader));
}

struct ClassRow {
  const char* id;    // as openNURBS's ON_OBJECT_IMPLEMENT line writes it
  const char* name;  // openNURBS's class name; legacy ids carry the name of the class openNURBS reads them as
  ClassReader read;  // nullptr: cadnurbs does not convert this class
};

// Class ids from openNURBS's ON_OBJECT_IMPLEMENT lines; the legacy ids ON_ClassId::ClassId demotes to
// current classes (TL_... from Rhino 1/2 era files, and the old V2 curve, surface and Brep ids) read as the
// class they are demoted to. Helpers: curves and surfaces (curve_objects, surface_objects), Brep and
// Extrusion (brep_object, extrusion_object), meshes (mesh_object), SubDs (subd_object).
const std::array kClasses = {
    // Curves.
    ClassRow{"4ED7D4DD-E947-11D3-BFE5-0010830122F0", "ON_NurbsCurve", &as_geometry<read_nurbs_curve>},
    ClassRow{"5EAF1119-0B51-11D4-BFFE-0010830122F0", "ON_NurbsCurve", &as_geometry<read_nurbs_curve>},  // TL_NurbsCurve
    ClassRow{"76A709D5-1550-11D4-8000-0010830122F0", "ON_NurbsCurve", &as_geometry<read_nurbs_curve>},  // old V2 curve
    ClassRow{"4ED7D4DB-E947-11D3-BFE5-0010830122F0", "ON_LineCurve", &as_geometry<read_line_curve>},
    ClassRow{"CF33BE2A-09B4-11D4-BFFB-0010830122F0", "ON_ArcCurve", &as_geometry<read_arc_curve>},
    ClassRow{"CF33BE29-09B4-11D4-BFFB-0010830122F0", "ON_ArcCurve", &as_geometry<read_obsolete_circle_curve>},  // old circle
    ClassRow{"4ED7D4E6-E947-11D3-BFE5-0010830122F0", "ON_PolylineCurve", &as_geometry<read_polyline_curve>},
    ClassRow{"4ED7D4E0-E947-11D3-BFE5-0010830122F0", "ON_PolyCurve", &as_geometry<read_poly_curve>},
    ClassRow{"EF638317-154B-11D4-8000-0010830122F0", "ON_PolyCurve", &as_geometry<read_poly_curve>},  // old V2 polycurve
    ClassRow{"4ED7D4D9-E947-11D3-BFE5-0010830122F0", "ON_CurveProxy", nullptr},  // never in a file: its Write returns false
    ClassRow{"4ED7D4D8-E947-11D3-BFE5-0010830122F0", "ON_CurveOnSurface", nullptr},
    ClassRow{"39FF3DD3-FE0F-4807-9D59-185F0D73C0E4", "ON_PolyEdgeCurve", nullptr},
    ClassRow{"42F47A87-5B1B-4E31-AB87-4639D78325D6", "ON_PolyEdgeSegment", nullptr},  // refers to another object's Brep edge: no geometry
    // Surfaces.
    ClassRow{"4ED7D4DE-E947-11D3-BFE5-0010830122F0", "ON_NurbsSurface", &as_geometry<read_nurbs_surface>},
    ClassRow{"4760C817-0BE3-11D4-BFFE-0010830122F0", "ON_NurbsSurface", &as_geometry<read_nurbs_surface>},  // TL_NurbsSurface
    ClassRow{"FA4FD4B5-1613-11D4-8000-0010830122F0", "ON_NurbsSurface", &as_geometry<read_nurbs_surface>},  // old V2 surface
    ClassRow{"4ED7D4DF-E947-11D3-BFE5-0010830122F0", "ON_PlaneSurface", &as_geometry<read_plane_surface>},
    ClassRow{"A16220D3-163B-11D4-8000-0010830122F0", "ON_RevSurface", &as_geometry<read_rev_surface>},
    ClassRow{"0A8401B6-4D34-4B99-8615-1B4E723DC4E5", "ON_RevSurface", &as_geometry<read_rev_surface>},  // TL_RevSurface
    ClassRow{"C4CD5359-446D-4690-9FF5-29059732472B", "ON_SumSurface", &as_geometry<read_sum_surface>},
    ClassRow{"665F6331-2A66-4CCE-81D0-B5EEBD9B5417", "ON_SumSurface", &as_geometry<read_sum_surface>},  // TL_SumSurface
    ClassRow{"4ED7D4E2-E947-11D3-BFE5-0010830122F0", "ON_SurfaceProxy", nullptr},  // never in a file: its Write returns false
    ClassRow{"DBC5A584-CE3F-4170-98A8-497069CA5C36", "ON_ClippingPlaneSurface", nullptr},
    ClassRow{"00C61749-D430-4ECC-83A8-29130A20CF9C", "ON_OffsetSurface", nullptr},
    // Breps, extrusions, meshes, SubDs.
    ClassRow{"60B5DBC5-E660-11D3-BFE4-0010830122F0", "ON_Brep", &as_geometry<read_brep>},
    ClassRow{"F06FC243-A32A-4608-9DD8-A7D2C4CE2A36", "ON_Brep", &as_geometry<read_brep>},  // TL_Brep
    ClassRow{"0705FDEF-3E2A-11D4-800E-0010830122F0", "ON_Brep", &as_geometry<read_brep>},  // old trimmed surface
    ClassRow{"2D4CFEDB-3E2A-11D4-800E-0010830122F0", "ON_Brep", &as_geometry<read_brep>},  // old V2 Brep
    ClassRow{"36F53175-72B8-4D47-BF1F-B4E6FC24F4B9", "ON_Extrusion", &as_geometry<read_extrusion>},
    ClassRow{"4ED7D4E4-E947-11D3-BFE5-0010830122F0", "ON_Mesh", &as_geometry<read_mesh>},
    ClassRow{"F09BA4D9-455B-42C3-BA3B-E6CCACEF853B", "ON_SubD", &as_geometry<read_subd>},
    // Geometry cadnurbs does not convert.
    ClassRow{"2488F347-F8FA-11D3-BFEC-0010830122F0", "ON_PointCloud", nullptr},
    ClassRow{"C3101A1D-F157-11D3-BFE7-0010830122F0", "ON_Point", nullptr},
    ClassRow{"4ED7D4E5-E947-11D3-BFE5-0010830122F0", "ON_PointGrid", nullptr},
    ClassRow{"0559733B-5332-49D1-A936-0532AC76ADE5", "ON_Hatch", nullptr},
    ClassRow{"F9CFB638-B9D4-4340-87E3-C56E7865D96A", "ON_InstanceRef", nullptr},
    ClassRow{"74198302-CDF4-4F95-9609-6D684F22AB37", "ON_TextDot", nullptr},
    ClassRow{"57376349-62A9-4A16-B411-A46BCD544790", "ON_Text", nullptr},
    ClassRow{"945BF594-6FF9-4F5C-BFC0-B3AF528F29D2", "ON_Leader", nullptr},
    ClassRow{"E550882B-F44D-4154-A1EF-6E50CBBBF543", "ON_DimLinear", nullptr},
    ClassRow{"D417786B-F6CD-4F12-9E1F-063F414DBEB6", "ON_DimAngular", nullptr},
    ClassRow{"FC749C2F-4C00-41FD-9840-26D94F047AD3", "ON_DimRadial", nullptr},
    ClassRow{"03124828-4C9B-4D28-9A82-664DDDE7A14F", "ON_DimOrdinate", nullptr},
    ClassRow{"D46767BA-7E8F-4D9D-9A92-66050219A5B9", "ON_Centermark", nullptr},
    ClassRow{"46F75541-F46B-48BE-AA7E-B353BBE068A7", "ON_OBSOLETE_V5_TextObject", nullptr},
    ClassRow{"14922B7A-5B65-4F11-8345-D415A9637129", "ON_OBSOLETE_V5_Leader", nullptr},
    ClassRow{"BD57F33B-A1B2-46E9-9C6E-AF09D30FFDDE", "ON_OBSOLETE_V5_DimLinear", nullptr},
    ClassRow{"841BC40B-A971-4A8E-94E5-BBA26D67348E", "ON_OBSOLETE_V5_DimAngular", nullptr},
    ClassRow{"B2B683FC-7964-4E96-B1F9-9B356A76B08B", "ON_OBSOLETE_V5_DimRadial", nullptr},
    ClassRow{"C8288D69-5BD8-4F50-9BAF-525A0086B0C3", "ON_OBSOLETE_V5_DimOrdinate", nullptr},
    ClassRow{"5DE6B210-486B-11D4-8014-0010830122F0", "ON_OBSOLETE_V2_TextObject", nullptr},
    ClassRow{"5DE6B211-486B-11D4-8014-0010830122F0", "ON_OBSOLETE_V2_Leader", nullptr},
    ClassRow{"5DE6B20D-486B-11D4-8014-0010830122F0", "ON_OBSOLETE_V2_DimLinear", nullptr},
    ClassRow{"5DE6B20F-486B-11D4-8014-0010830122F0", "ON_OBSOLETE_V2_DimAngular", nullptr},
    ClassRow{"5DE6B20E-486B-11D4-8014-0010830122F0", "ON_OBSOLETE_V2_DimRadial", nullptr},
    ClassRow{"8BD94E19-59E1-11D4-8018-0010830122F0", "ON_OBSOLETE_V2_TextDot", nullptr},
    ClassRow{"8BD94E1A-59E1-11D4-8018-0010830122F0", "ON_OBSOLETE_V2_AnnotationArrow", nullptr},
    ClassRow{"C8C66EFA-B3CB-4E00-9440-2AD66203379E", "ON_DetailView", nullptr},
    ClassRow{"85A08513-F383-11D3-BFE7-0010830122F0", "ON_Light", nullptr},
    ClassRow{"06936AFB-3D3C-41AC-BF70-C9319FA480A1", "ON_NurbsCage", nullptr},
    ClassRow{"D379E6D8-7C31-4407-A913-E3B7040D034A", "ON_MorphControl", nullptr},
    ClassRow{"D66E5CCF-EA39-11D3-BFE5-0010830122F0", "ON_Viewport", nullptr},
    // Table records (named in messages about table entries).
    ClassRow{"95809813-E985-11D3-BFE5-0010830122F0", "ON_Layer", nullptr},
    ClassRow{"60B5DBBC-E660-11D3-BFE4-0010830122F0", "ON_Material", nullptr},
    ClassRow{"26F10A24-7D13-4F05-8FDA-8E364DAF8EA6", "ON_Linetype", nullptr},
    ClassRow{"721D9F97-3645-44C4-8BE6-B2CF697D25CE", "ON_Group", nullptr},
    ClassRow{"26F8BFF6-2618-417F-A158-153D64A94989", "ON_InstanceDefinition", nullptr},
    ClassRow{"A828C015-09F5-477C-8665-F0482F5D6996", "ON_3dmObjectAttributes", nullptr},
};

const ClassRow* find_class(const Uuid& id) {
  const std::string text = id.text();
  const auto row = std::find_if(kClasses.begin(), kClasses.end(), [&](const ClassRow& r) { return text == r.id; });
  return row == kClasses.end() ? nullptr : &*row;
}

}  // namespace

std::string class_name(const Uuid& class_id) {
  const ClassRow* row = find_class(class_id);
  return row ? row->name : "";
}

RhinoGeometry read_object(ArchiveReader& reader) {
  reader.begin_chunk(tcode::kOpennurbsClass);
  reader.begin_chunk(tcode::kOpennurbsClassUuid);
  const Uuid id = reader.uuid();
  reader.end_chunk();
  if (id == Uuid{}) {  // WriteObject's form of a null pointer: no data follows
    reader.end_chunk();
    return Unsupported{"null"};
  }
  const ClassRow* row = find_class(id);
  RhinoGeometry geometry = Unsupported{row ? row->name : id.text()};
  if (row && row->read) {
    reader.begin_chunk(tcode::kOpennurbsClassData);
    geometry = row->read(reader);
    reader.end_chunk();
  }
  reader.end_chunk();  // user data and the end mark are not read
  return geometry;
}

}  // namespace cadnurbs::rhino
