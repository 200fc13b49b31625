#ifndef GLTestErrorObserver_h
#define GLTestErrorObserver_h
/**
 * @file GLTestErrorObserver.h
 * @brief Test helper: records the ErrorEvents (and WarningEvents) of a VTK object so that a
 * filter test can assert "an error was reported, with this text" without the message being
 * printed. (vtkObject::GlobalWarningDisplayOff() would suppress the events themselves.)
 *
 *   vtkNew<GLTestErrorObserver> errors;
 *   errors->Observe(filter);
 *   filter->Update();
 *   EXPECT_TRUE(errors->HasError());
 *   EXPECT_NE(errors->Errors().find("file not found"), std::string::npos);
 */
#include <vtkCommand.h>
#include <vtkObject.h>

#include <string>

class GLTestErrorObserver : public vtkCommand {
public:
  static GLTestErrorObserver* New() { return new GLTestErrorObserver; }
  vtkTypeMacro(GLTestErrorObserver, vtkCommand);

  /// Start recording the errors and warnings of `object`.
  void Observe(vtkObject* object) {
    object->AddObserver(vtkCommand::ErrorEvent, this);
    object->AddObserver(vtkCommand::WarningEvent, this);
  }

  void Execute(vtkObject*, unsigned long event, void* callData) override {
    const std::string text = callData ? static_cast<const char*>(callData) : "";
    if (event == vtkCommand::ErrorEvent) {
      ++this->ErrorCount;
      this->ErrorText += text + "\n";
    } else if (event == vtkCommand::WarningEvent) {
      ++this->WarningCount;
      this->WarningText += text + "\n";
    }
  }

  bool HasError() const { return this->ErrorCount > 0; }
  int GetErrorCount() const { return this->ErrorCount; }
  int GetWarningCount() const { return this->WarningCount; }
  const std::string& Errors() const { return this->ErrorText; }
  const std::string& Warnings() const { return this->WarningText; }
  void Clear() {
    this->ErrorCount = this->WarningCount = 0;
    this->ErrorText.clear();
    this->WarningText.clear();
  }

private:
  int ErrorCount = 0;
  int WarningCount = 0;
  std::string ErrorText;
  std::string WarningText;
};

#endif
