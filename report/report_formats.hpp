#pragma once
// The report's layouts of PartRecords (storage_record.hpp). Every layout carries the accounting rule and,
// except CSV (one row per part, for spreadsheets), the papers' reference figures labelled as theirs.
// The JSON schema is documented in docs/report.md; CSV columns are the JSON record's scalars flattened
// ("x3dv-compact.gzip_bytes"), representations in the order of their first appearance.
#include <string>
#include <vector>

#include "report/storage_record.hpp"

namespace cadnurbs {

// A Markdown document: the combined table (one row per part), the failed inputs with their reasons,
// one table per part (every representation: bytes, gzip'd, floats, integers, deviation), the reference
// figures.
std::string report_markdown(const std::vector<PartRecord>& records);

// The combined table alone (one row per measured part), as `demo` prints it.
std::string report_markdown_parts(const std::vector<PartRecord>& records);

// {"cadnurbs_report": 1, "accounting": ..., "reference_figures": [...], "parts": [record...]}
std::string report_json(const std::vector<PartRecord>& records);

// One JSON record (what `parts` holds; its keys: record_fields.hpp), for tools that keep per-part files.
std::string part_record_json(const PartRecord& record);

// Header line + one line per part (RFC 4180 quoting).
std::string report_csv(const std::vector<PartRecord>& records);

// A figure for a table: number_text with `digits` significant digits, "-" for NaN (not measured).
std::string report_number(double value, int digits = 4);

// A representation's deviation as every table prints it, with how it is known: "0.0072 bound",
// "0.0081 measured", "-" when not known.
std::string labelled_deviation(const RepresentationFigures& figures);

// The sentence that states the accounting (seed 001, §6.1), as every layout prints it.
const std::string& accounting_rule();

}  // namespace cadnurbs
