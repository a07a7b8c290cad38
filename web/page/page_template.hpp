#pragma once
// A page template's @KEY@ markers filled in (web/viewer's page.html and site_page.html).
#include <map>
#include <string>

namespace cadnurbs {

// `page` with each @KEY@ of `values` replaced by its value, in one pass: what a value holds is never read as
// a marker, and an @ that starts no known marker stays.
std::string filled_template(const std::string& page, const std::map<std::string, std::string>& values);

}  // namespace cadnurbs
