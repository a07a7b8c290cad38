#include "formats/brep/occt_setup.hpp"

#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <OSD.hxx>
#include <mutex>

namespace cadnurbs {

void prepare_occt() {
  static std::once_flag once;
  std::call_once(once, [] {
    Message::DefaultMessenger()->ChangePrinters().Clear();
    OSD::SetSignal(OSD_SignalMode_SetUnhandled, /*theFloatingSignal=*/false);
  });
}

}  // namespace cadnurbs
