#pragma once
// Process-wide OCCT settings for the readers and writers. No OCCT types.

namespace cadnurbs {

// Call before any OCCT reading or writing; only the first call acts, the others return at once.
// - OCCT's default messenger loses its printers: OCCT prints progress and warnings to stdout, and the
//   one-line error cadnurbs gives must be all the user sees.
// - Crash signals (SIGSEGV, SIGBUS, SIGILL; not floating-point traps) get OCCT's handlers where the
//   application has none, so inside OCC_CATCH_SIGNALS a crash in OCCT (seen on damaged STEP files)
//   becomes a Standard_Failure instead of killing the process.
void prepare_occt();

}  // namespace cadnurbs
