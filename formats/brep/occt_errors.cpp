#include "formats/brep/occt_errors.hpp"

#include <Interface_Check.hxx>
#include <TCollection_HAsciiString.hxx>
#include <algorithm>
#include <cctype>
#include <regex>

#include "formats/common/file_io.hpp"

namespace cadnurbs {

namespace {

bool mentions_unresolved(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text.find("unresolved") != std::string::npos;
}

}  // namespace

std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::replace(text.begin(), text.end(), '\r', ' ');
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

std::string occt_failure_text(const Standard_Failure& failure) {
  const char* message = failure.GetMessageString();
  // What OCC_CATCH_SIGNALS throws after a crash (a segmentation fault, mostly).
  if (message && std::string(message).find("System Signal received") != std::string::npos)
    return "OCCT crashed (" + std::string(failure.DynamicType()->Name()) + ": a system signal)";
  std::string text = std::string("OCCT ") + failure.DynamicType()->Name();
  if (message && *message) text += std::string(": ") + message;
  return one_line(text);
}

std::string read_status_text(IFSelect_ReturnStatus status) {
  switch (status) {
    case IFSelect_RetVoid: return "the file holds nothing OCCT can read";
    case IFSelect_RetDone: return "no error";
    case IFSelect_RetError: return "OCCT reports an error in the file";
    case IFSelect_RetFail: return "OCCT cannot parse the file";
    case IFSelect_RetStop: return "OCCT stopped reading";
  }
  return "unknown OCCT status " + std::to_string(static_cast<int>(status));
}

void refuse_unresolved_references(const Interface_CheckIterator& checks, const Handle(Interface_InterfaceModel)& model,
                                  const std::string& path, const std::string& format) {
  int count = 0;
  std::string first;
  Interface_CheckIterator it = checks;
  for (it.Start(); it.More(); it.Next()) {
    const Handle(Interface_Check)& check = it.Value();
    for (int i = 1; i <= check->NbFails(); ++i) {
      const std::string message = check->CFail(i, /*final=*/true);
      if (!mentions_unresolved(check->CFail(i, false)) && !mentions_unresolved(message)) continue;
      if (count++ > 0) continue;
      // OCCT's STEP reader says "Unresolved Reference, Ent.Id.#12 Param.n0 3 (Id.#345)".
      const std::regex step_form(R"(Ent\.Id\.(#-?\d+).*\(Id\.(#\d+)\))");
      std::smatch match;
      if (std::regex_search(message, match, step_form) && match[1].str() != "#-3") {
        first = "entity " + match[1].str() + " refers to " + match[2].str() + ", which the file lacks";
      } else if (std::regex_search(message, match, std::regex(R"(\(Id\.(#\d+)\))"))) {
        first = "an entity refers to " + match[1].str() + ", which the file lacks";
      } else if (it.Number() >= 1 && !model.IsNull() && it.Number() <= model->NbEntities()) {
        const Handle(TCollection_HAsciiString) label = model->StringLabel(model->Value(it.Number()));
        first = "entity " + std::string(label.IsNull() ? std::to_string(it.Number()) : label->ToCString()) +
                " refers to an entity the file lacks";
      } else {
        first = one_line(message);
      }
    }
  }
  if (count > 0)
    throw FileError(path + ": " + format + " read failed: " + first + " (" + std::to_string(count) +
                    " unresolved reference" + (count > 1 ? "s" : "") + ")");
}

}  // namespace cadnurbs
