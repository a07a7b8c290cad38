#include <cctype>
#include <cmath>
#include <filesystem>
#include <iostream>

#include "converters/arguments.hpp"
#include "converters/commands.hpp"
#include "converters/file_formats.hpp"
#include "converters/path_fitting.hpp"
#include "core/number_format.hpp"
#include "formats/common/file_io.hpp"
#include "formats/common/gzip.hpp"

namespace cadnurbs {

// The description tells what D is: no option needs a line of its own.
const CommandSpec& fit_path_command_spec() {
  static const CommandSpec spec = {
      "fit-path",
      "IN -o OUT --deviation D",
      "Rewrites every PositionInterpolator of a VRML97 or X3D file (classic or XML, gzip'd or not) as a\n"
      "NurbsPositionInterpolator: a polynomial NURBS curve, knots on [0, 1] so that the fraction is the\n"
      "curve parameter, within D (model units) of the original path at every fraction, keys and between\n"
      "keys alike (the bound is certified on the curve as written). DEF names and ROUTEs are kept and every\n"
      "other byte passes through. VRML97 output declares the node by EXTERNPROTO and gets the PROTO library\n"
      "beside it; X3D output gets the NURBS component. OrientationInterpolators are left as they are. OUT\n"
      "must be of IN's encoding (.wrl/.wrz, .x3dv/.x3dvz, .x3d/.x3dz).",
      {{"output", "OUT", ""}, {"deviation", "D", ""}},
      "",
  };
  return spec;
}

namespace {

const char* encoding_name(VrmlEncoding encoding) {
  switch (encoding) {
    case VrmlEncoding::vrml97: return "VRML97";
    case VrmlEncoding::x3d_classic: return "X3D classic";
    case VrmlEncoding::x3d_xml: return "X3D XML";
  }
  return "";
}

// The encoding a text is in, by its first bytes.
VrmlEncoding encoding_of_text(const std::string& text, const std::string& path) {
  if (text.rfind("#VRML V2.0", 0) == 0) return VrmlEncoding::vrml97;
  if (text.rfind("#X3D", 0) == 0) return VrmlEncoding::x3d_classic;
  size_t i = text.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;
  while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  if (i < text.size() && text[i] == '<') return VrmlEncoding::x3d_xml;
  throw FileError(path + ": not a VRML97 (#VRML V2.0), X3D classic (#X3D) or X3D XML file");
}

}  // namespace

int run_fit_path(const std::vector<std::string>& args, const CommandContext&) {
  const Arguments a = parse_arguments(fit_path_command_spec(), args);
  if (a.has("help")) {
    std::cout << command_help(fit_path_command_spec());
    return 0;
  }
  if (a.positional.size() != 1 || !a.has("output") || !a.has("deviation"))
    throw UsageError("needs one input, -o OUT and --deviation D (see --help)");
  const std::string in = a.positional[0], out = a.value("output");
  const double deviation = a.number("deviation", 0);
  if (!(deviation > 0 && std::isfinite(deviation))) throw UsageError("--deviation must be > 0");
  std::error_code ec;
  if (std::filesystem::equivalent(in, out, ec)) throw UsageError(out + ": output would overwrite the input");
  const std::optional<VrmlTextForm> form = vrml_text_form(output_format(out));
  if (!form) throw UsageError(out + ": fit-path writes VRML97 or X3D (.wrl, .x3dv, .x3d and their gzip'd forms)");

  const std::string bytes = read_file(in);
  const std::string text = is_gzip(bytes) ? gunzip(bytes, in) : bytes;
  const VrmlEncoding encoding = encoding_of_text(text, in);
  if (encoding != form->encoding)
    throw UsageError(out + ": fit-path keeps the file's encoding: " + in + " is " + encoding_name(encoding) + ", " +
                     out + " would be " + encoding_name(form->encoding));
  const std::string protos_url = VrmlWriteOptions().protos_url;
  const PathRewrite rewrite = fit_paths_in_text(text, encoding, deviation, protos_url, in);
  write_file_atomically(out, form->gzipped ? gzip(rewrite.text) : rewrite.text);
  bool declares_protos = false;
  for (const PathAccount& p : rewrite.accounts) declares_protos |= p.converted;
  if (declares_protos && encoding == VrmlEncoding::vrml97) write_nurbs_protos_beside(out, protos_url);

  int converted = 0;
  for (const PathAccount& p : rewrite.accounts) {
    const std::string name = p.type + (p.def_name.empty() ? "" : " " + p.def_name) + " (line " +
                             std::to_string(p.line) + ")";
    if (p.converted) {
      ++converted;
      std::cout << in << ": " << name << ": " << p.keys << " keys -> " << p.control_points
                << " control points (order " << p.order << "), max error " << message_number(p.max_error)
                << " (bound), " << p.bytes_before << " -> " << p.bytes_after << " bytes\n";
    } else {
      std::cout << in << ": " << name << ": " << p.keys << " keys, left as it is: " << p.left_because << "\n";
    }
  }
  std::cout << out << ": " << converted << " of " << rewrite.accounts.size() << " interpolators fitted within "
            << message_number(deviation) << "; " << text.size() << " -> " << rewrite.text.size() << " bytes ("
            << gzip(text).size() << " -> " << gzip(rewrite.text).size() << " gzip'd)\n";
  return 0;
}

}  // namespace cadnurbs
