#pragma once
// OCCT's ways of failing, as the one-line causes cadnurbs reports. Internal to formats/brep, step and
// iges: includes OCCT.
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_CheckIterator.hxx>
#include <Interface_InterfaceModel.hxx>
#include <Standard_Failure.hxx>
#include <string>

namespace cadnurbs {

// `text` with line breaks turned into spaces and trailing spaces dropped (messages are one line).
std::string one_line(std::string text);

// "OCCT <exception class>: <message>" on one line; "OCCT crashed (...)" for a crash OCC_CATCH_SIGNALS caught.
std::string occt_failure_text(const Standard_Failure& failure);

// What a reader's ReadFile status means: "the file holds nothing OCCT can read", "syntax error", ...
std::string read_status_text(IFSelect_ReturnStatus status);

// Throws FileError "<path>: <format> read failed: entity #n refers to #m, which the file lacks (K unresolved
// references)" when the model's checks report unresolved references (a damaged or truncated file: OCCT
// would silently read what is left).
void refuse_unresolved_references(const Interface_CheckIterator& checks, const Handle(Interface_InterfaceModel)& model,
                                  const std::string& path, const std::string& format);

}  // namespace cadnurbs
