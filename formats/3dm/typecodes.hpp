#pragma once
// The chunk typecodes of the openNURBS archive that cadnurbs reads (the facts of opennurbs_3dm.h). A
// typecode's high bits say what kind of chunk it is: kShort (value is the data, no body), kCrc (the body
// ends in a CRC-32), kTable / kTableRecord (a table of the file and its records).
#include <cstdint>

namespace cadnurbs::rhino::tcode {

// Category bits.
inline constexpr std::uint32_t kLegacyGeometry = 0x00010000u;
inline constexpr std::uint32_t kOpennurbsObject = 0x00020000u;
inline constexpr std::uint32_t kGeometry = 0x00100000u;
inline constexpr std::uint32_t kAnnotation = 0x00200000u;
inline constexpr std::uint32_t kDisplay = 0x00400000u;
inline constexpr std::uint32_t kRender = 0x00800000u;
inline constexpr std::uint32_t kInterface = 0x02000000u;
inline constexpr std::uint32_t kTolerance = 0x08000000u;
inline constexpr std::uint32_t kTable = 0x10000000u;
inline constexpr std::uint32_t kTableRecord = 0x20000000u;
inline constexpr std::uint32_t kUser = 0x40000000u;
inline constexpr std::uint32_t kShort = 0x80000000u;
inline constexpr std::uint32_t kCrc = 0x00008000u;

// The file's frame.
inline constexpr std::uint32_t kCommentBlock = 0x00000001u;
inline constexpr std::uint32_t kEndOfFile = 0x00007FFFu;
inline constexpr std::uint32_t kEndOfTable = 0xFFFFFFFFu;

// Generic chunks objects write inside their data.
inline constexpr std::uint32_t kAnonymousChunk = kUser | kCrc | 0x0000u;
inline constexpr std::uint32_t kUtf8StringChunk = kUser | kCrc | 0x0001u;
inline constexpr std::uint32_t kModelAttributesChunk = kUser | kCrc | 0x0002u;
inline constexpr std::uint32_t kOpennurbsBuffer = kOpennurbsObject | kCrc | 0x0100u;

// Tables, in the order a V2+ file writes them (not every file has every table).
inline constexpr std::uint32_t kPropertiesTable = kTable | 0x0014u;
inline constexpr std::uint32_t kSettingsTable = kTable | 0x0015u;
inline constexpr std::uint32_t kBitmapTable = kTable | 0x0016u;
inline constexpr std::uint32_t kTextureMappingTable = kTable | 0x0025u;
inline constexpr std::uint32_t kMaterialTable = kTable | 0x0010u;
inline constexpr std::uint32_t kLinetypeTable = kTable | 0x0023u;
inline constexpr std::uint32_t kLayerTable = kTable | 0x0011u;
inline constexpr std::uint32_t kGroupTable = kTable | 0x0018u;
inline constexpr std::uint32_t kFontTable = kTable | 0x0019u;
inline constexpr std::uint32_t kDimstyleTable = kTable | 0x0020u;
inline constexpr std::uint32_t kLightTable = kTable | 0x0012u;
inline constexpr std::uint32_t kHatchPatternTable = kTable | 0x0022u;
inline constexpr std::uint32_t kInstanceDefinitionTable = kTable | 0x0021u;
inline constexpr std::uint32_t kObjectTable = kTable | 0x0013u;
inline constexpr std::uint32_t kHistoryRecordTable = kTable | 0x0026u;
inline constexpr std::uint32_t kUserTable = kTable | 0x0017u;

// Properties table records.
inline constexpr std::uint32_t kPropertiesRevisionHistory = kTableRecord | kCrc | 0x0021u;
inline constexpr std::uint32_t kPropertiesNotes = kTableRecord | kCrc | 0x0022u;
inline constexpr std::uint32_t kPropertiesPreviewImage = kTableRecord | kCrc | 0x0023u;
inline constexpr std::uint32_t kPropertiesApplication = kTableRecord | kCrc | 0x0024u;
inline constexpr std::uint32_t kPropertiesCompressedPreviewImage = kTableRecord | kCrc | 0x0025u;
inline constexpr std::uint32_t kPropertiesOpennurbsVersion = kTableRecord | kShort | 0x0026u;
inline constexpr std::uint32_t kPropertiesAsFileName = kTableRecord | kCrc | 0x0027u;

// Settings table records.
inline constexpr std::uint32_t kSettingsUnitsAndTolerances = kTableRecord | kCrc | 0x0031u;
inline constexpr std::uint32_t kSettingsPluginList = kTableRecord | kCrc | 0x0135u;

// Table records.
inline constexpr std::uint32_t kBitmapRecord = kTableRecord | kCrc | 0x0090u;
inline constexpr std::uint32_t kMaterialRecord = kTableRecord | kCrc | 0x0040u;
inline constexpr std::uint32_t kLayerRecord = kTableRecord | kCrc | 0x0050u;
inline constexpr std::uint32_t kLightRecord = kTableRecord | kCrc | 0x0060u;
inline constexpr std::uint32_t kGroupRecord = kTableRecord | kCrc | 0x0073u;
inline constexpr std::uint32_t kFontRecord = kTableRecord | kCrc | 0x0074u;
inline constexpr std::uint32_t kDimstyleRecord = kTableRecord | kCrc | 0x0075u;
inline constexpr std::uint32_t kInstanceDefinitionRecord = kTableRecord | kCrc | 0x0076u;
inline constexpr std::uint32_t kHatchPatternRecord = kTableRecord | kCrc | 0x0077u;
inline constexpr std::uint32_t kLinetypeRecord = kTableRecord | kCrc | 0x0078u;
inline constexpr std::uint32_t kTextureMappingRecord = kTableRecord | kCrc | 0x007Au;
inline constexpr std::uint32_t kHistoryRecordRecord = kTableRecord | kCrc | 0x007Bu;

// Object table: a record holds its type, the object, its attributes, optional history, and an end mark.
inline constexpr std::uint32_t kObjectRecord = kTableRecord | kCrc | 0x0070u;
inline constexpr std::uint32_t kObjectRecordType = kInterface | kShort | 0x0071u;  // ON::object_type
inline constexpr std::uint32_t kObjectRecordAttributes = kInterface | kCrc | 0x0072u;
inline constexpr std::uint32_t kObjectRecordAttributesUserData = kInterface | 0x0073u;
inline constexpr std::uint32_t kObjectRecordHistory = kInterface | kCrc | 0x0074u;
inline constexpr std::uint32_t kObjectRecordEnd = kInterface | kShort | 0x007Fu;

// One openNURBS object (ON_BinaryArchive::WriteObject): class id, class data, user data, end.
inline constexpr std::uint32_t kOpennurbsClass = kOpennurbsObject | 0x7FFAu;
inline constexpr std::uint32_t kOpennurbsClassUuid = kOpennurbsObject | kCrc | 0x7FFBu;
inline constexpr std::uint32_t kOpennurbsClassData = kOpennurbsObject | kCrc | 0x7FFCu;
inline constexpr std::uint32_t kOpennurbsClassUserData = kOpennurbsObject | 0x7FFDu;
inline constexpr std::uint32_t kOpennurbsClassUserDataHeader = kOpennurbsObject | kCrc | 0x7FF9u;
inline constexpr std::uint32_t kOpennurbsClassEnd = kOpennurbsObject | kShort | 0x7FFFu;

// Short chunks whose 4-byte value (archive versions < 50) is unsigned; every other short value is signed.
inline constexpr std::uint32_t kRgb = kShort | kDisplay | 0x0001u;
inline constexpr std::uint32_t kRgbDisplay = kShort | kDisplay | 0x0006u;

// Version 1 files: legacy geometry and interface chunks instead of tables. Each legacy geometry chunk
// wraps one "stuff" chunk (its code | kLegacyStuff) that holds the record.
inline constexpr std::uint32_t kSummary = kInterface | 0x0013u;
inline constexpr std::uint32_t kLegacyStuff = 0x0100u;
inline constexpr std::uint32_t kLegacyShell = kLegacyGeometry | 0x0003u;  // a polysurface
inline constexpr std::uint32_t kLegacyFace = kLegacyGeometry | 0x0004u;   // a trimmed surface
inline constexpr std::uint32_t kLegacyLoop = kLegacyGeometry | 0x0005u;   // "boundary"
inline constexpr std::uint32_t kLegacyTrim = kLegacyGeometry | 0x0006u;
inline constexpr std::uint32_t kLegacySurface = kLegacyGeometry | 0x0007u;
inline constexpr std::uint32_t kLegacyCurve = kLegacyGeometry | 0x0008u;
inline constexpr std::uint32_t kLegacySpline = kLegacyGeometry | 0x0009u;
inline constexpr std::uint32_t kLegacyShellStuff = kLegacyShell | kLegacyStuff;
inline constexpr std::uint32_t kLegacyFaceStuff = kLegacyFace | kLegacyStuff;
inline constexpr std::uint32_t kLegacyLoopStuff = kLegacyLoop | kLegacyStuff;
inline constexpr std::uint32_t kLegacyTrimStuff = kLegacyTrim | kLegacyStuff;
inline constexpr std::uint32_t kLegacySurfaceStuff = kLegacySurface | kLegacyStuff;
inline constexpr std::uint32_t kLegacyCurveStuff = kLegacyCurve | kLegacyStuff;
inline constexpr std::uint32_t kLegacySplineStuff = kLegacySpline | kLegacyStuff;
inline constexpr std::uint32_t kMeshObject = kGeometry | 0x0015u;              // a V1 mesh
inline constexpr std::uint32_t kCompressedMeshGeometry = kGeometry | 0x0017u;  // its data
inline constexpr std::uint32_t kRhPoint = kGeometry | 0x0001u;     // a V1 point (not read)
// V1 object attributes (chunks in front of an object's stuff chunk) and layers.
inline constexpr std::uint32_t kName = kInterface | 0x0001u;              // int32 length, that many chars
inline constexpr std::uint32_t kUnitAndTolerances = kInterface | 0x0010u;
inline constexpr std::uint32_t kLayerRef = kShort | kTableRecord | 0x0001u;  // value: the layer's index
inline constexpr std::uint32_t kV1Layer = kDisplay | 0x0010u;                // holds the chunks below
inline constexpr std::uint32_t kV1LayerName = kDisplay | 0x0011u;            // int32 length, chars

}  // namespace cadnurbs::rhino::tcode
