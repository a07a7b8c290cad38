#pragma once
// DEF names: node and shape names turned into identifiers legal in VRML97, X3D classic and X3D XML
// (an XML ID too), unique within one file.
#include <set>
#include <string>

namespace cadnurbs {

// `name` with every character outside [A-Za-z0-9_-] replaced by '_' (one per UTF-8 sequence), a '_'
// in front of a leading digit or '-', and a '_' after a reserved word (TRUE, ROUTE, field...).
// An empty name gives "_".
std::string sanitised_identifier(const std::string& name);

// Whether `identifier` has the form the writer gives the nodes it DEFs for its own sake (shared
// geometry, appearances): "_" and digits. Such a DEF names nothing unless a WorldInfo "name" line says so.
bool is_generated_identifier(const std::string& identifier);

// Hands out identifiers that are unique within one file.
class IdentifierRegistry {
 public:
  // sanitised_identifier(wanted), with "_2", "_3"... appended until it is unused; marks it used.
  std::string claim(const std::string& wanted);
  // The next unused generated identifier ("_1", "_2"...); marks it used.
  std::string claim_generated();
  bool is_taken(const std::string& identifier) const { return taken_.count(identifier) != 0; }

 private:
  std::set<std::string> taken_;
  int generated_ = 0;
};

}  // namespace cadnurbs
