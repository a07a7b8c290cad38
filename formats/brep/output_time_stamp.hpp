#pragma once
// The time written into the headers of STEP and IGES files. No OCCT types.
#include <string>

namespace cadnurbs {

// "YYYY-MM-DDThh:mm:ss" (UTC): the time SOURCE_DATE_EPOCH names when that environment variable holds a
// number of seconds (the reproducible-builds convention, so regenerated samples are byte for byte the same),
// else the current time.
std::string output_time_stamp();

}  // namespace cadnurbs
