#pragma once
/// @file ErrorCapture.h
/// @brief The first error message VTK algorithms report, as one clean line for the CLI (instead of
/// VTK's multi-line console text).
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkNew.h>
#include <vtkObject.h>

#include <string>

namespace geolattice {

/// Captures the first error an algorithm reports (instead of VTK's multi-line console text).
class ErrorCapture {
public:
  void Watch(vtkObject* object) {
    vtkNew<vtkCallbackCommand> cb;
    cb->SetClientData(this);
    cb->SetCallback([](vtkObject*, unsigned long, void* self, void* callData) {
      auto* me = static_cast<ErrorCapture*>(self);
      if (me->Message.empty() && callData) {
        me->Message = Clean(static_cast<const char*>(callData));
      }
    });
    object->AddObserver(vtkCommand::ErrorEvent, cb);
  }
  std::string Message;

private:
  // "ERROR: In file, line N\nvtkClass (0x...): text\n\n" -> "text"
  static std::string Clean(std::string text) {
    const size_t paren = text.find("): ");
    if (paren != std::string::npos) {
      text = text.substr(paren + 3);
    }
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) {
      text.pop_back();
    }
    for (char& c : text) {
      if (c == '\n') {
        c = ' ';
      }
    }
    return text;
  }
};

}  // namespace geolattice
