#pragma once
// The batch's parent made warm before it forks its workers: OpenCASCADE's STEP and IGES translators
// set up (their protocols, their static tables) and the dynamic linker's symbol lookups for the read
// path done, once, so that no worker (and no worker's reading child, a fork of it) pays for them per
// part. The parent writes a one-face part as STEP and as IGES into a temporary folder and reads both
// back in its own process.
namespace cadnurbs {

// Never fails: warming is an economy, not a step a part depends on (a failure leaves the workers to
// start cold, as they would without it). Call it while the process runs one thread, before forking.
void warm_up_readers();

}  // namespace cadnurbs
