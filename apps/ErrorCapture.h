#pragma once
/// @file ErrorCapture.h
/// @brief The first error message VTK algorithms report, as one clean line for the CLI (instead of
/// VTK's multi-line console text).
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkNew.h>
#include <vtkObject.h>
#include <vtkSmartPointer.h>

#include <string>
#include <utility>
#include <vector>

namespace geolattice {

/// Captures the first error the watched objects report (instead of VTK's multi-line console
/// text) while it lives: the destructor removes its observers.
class ErrorCapture {
public:
  ErrorCapture() = default;
  ErrorCapture(const ErrorCapture&) = delete;
  ErrorCapture& operator=(const ErrorCapture&) = delete;
  ~ErrorCapture() {
    for (const auto& [object, tag] : this->Observers) {
      object->RemoveObserver(tag);
    }
  }

  void Watch(vtkObject* object) {
    vtkNew<vtkCallbackCommand> cb;
    cb->SetClientData(this);
    cb->SetCallback([](vtkObject*, unsigned long, void* self, void* callData) {
      auto* me = static_cast<ErrorCapture*>(self);
      if (me->Message.empty() && callData) {
        me->Message = Clean(static_cast<const char*>(callData));
      }
    });
    this->Observers.emplace_back(object, object->AddObserver(vtkCommand::ErrorEvent, cb));
  }
  std::string Message;

private:
  std::vector<std::pair<vtkSmartPointer<vtkObject>, unsigned long>> Observers;

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
