#pragma once
// OpenCASCADE's message machinery, tamed: no banners on stdout, readable shape-healing texts.
// geom/ sources only.
#include <Message_Msg.hxx>

#include <string>

namespace tubemesh::geom {

// Removes OCCT's default stdout printer (the STEP/IGES translators print banners and progress
// there, which would mix with the CLI's own output). Idempotent and thread-safe.
void silence_occt_output();

// Loads OCCT's shape-healing texts (resource file SHMessage/SHAPE.us). Call it before running
// ShapeFix: a message takes its text when it is created. Returns false when the file is not
// found; messages then read "Unknown message invoked with the keyword ...", key included.
bool load_healing_messages();

// The text of a shape-healing message with its arguments filled in.
std::string healing_message_text(const Message_Msg& msg);

}  // namespace tubemesh::geom
