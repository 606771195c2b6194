#include "geom/import/occt_messages.hpp"

#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_MsgFile.hxx>
#include <Message_PrinterOStream.hxx>
#include <OSD_Environment.hxx>
#include <TCollection_AsciiString.hxx>
#include <TCollection_ExtendedString.hxx>

#include <mutex>

namespace tubemesh::geom {

void silence_occt_output() {
    static std::once_flag once;
    std::call_once(once, [] {
        Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
    });
}

namespace {

// Where the SHAPE message file may be: OCCT's own variables first, then Debian's install path
// (the package sets no environment variable, so that is where it is in practice).
bool load_shape_messages_once() {
    if (Message_MsgFile::LoadFromEnv("CSF_SHMessage", "SHAPE")) return true;
    const TCollection_AsciiString resources = OSD_Environment("CSF_OCCTResourcePath").Value();
    if (!resources.IsEmpty() && Message_MsgFile::Load((resources + "/SHMessage").ToCString(), "SHAPE.us"))
        return true;
    return Message_MsgFile::Load("/usr/share/opencascade/resources/SHMessage", "SHAPE.us");
}

}  // namespace

bool load_healing_messages() {
    static std::once_flag once;
    static bool loaded = false;
    std::call_once(once, [] { loaded = load_shape_messages_once(); });
    return loaded;
}

std::string healing_message_text(const Message_Msg& msg) {
    Message_Msg filled(msg);  // Get() formats in place
    return TCollection_AsciiString(filled.Get()).ToCString();
}

}  // namespace tubemesh::geom
