/**
 * @file vtkGLOptionMacros.h
 * @brief Set/Get methods of a filter parameter that lives in the filter's core options struct.
 *
 * A filter holds its stage's core options (e.g. `geolattice::PedestalOptions Options;`), so each
 * parameter has one default, the core struct's, and RequestData hands `this->Options` to core as
 * it is. These macros declare the parameter's methods as vtkSetMacro/vtkGetMacro would for a
 * member of its own (VTK's wrappers expand them: ParaView's XML and Python see SetHeight,
 * GetHeight, ...). `field` is the member of `this->Options`.
 */
#ifndef vtkGLOptionMacros_h
#define vtkGLOptionMacros_h

#include <vtkSetGet.h>

#include <algorithm>  // std::clamp

/// The setters' one body: assigns `value` to `field` of `self`'s Options and calls Modified()
/// when it changes.
template <class Object, class Field, class Value>
void vtkGLAssignOption(Object* self, Field& field, const Value& value) {
  if (field != value) {
    field = value;
    self->Modified();
  }
}

/// Set##name / Get##name for this->Options.field (Modified() when the value changes).
#define vtkGLOptionMacro(name, type, field)             \
  virtual void Set##name(type _arg) {                   \
    vtkGLAssignOption(this, this->Options.field, _arg); \
  }                                                     \
  virtual type Get##name() {                            \
    return this->Options.field;                         \
  }

/// The same, the value clamped to [min, max] as vtkSetClampMacro does.
#define vtkGLOptionClampMacro(name, type, field, min, max)                          \
  virtual void Set##name(type _arg) {                                               \
    vtkGLAssignOption(this, this->Options.field, std::clamp<type>(_arg, min, max)); \
  }                                                                                 \
  virtual type Get##name() {                                                        \
    return this->Options.field;                                                     \
  }

/// An enum option as an int property clamped to [min, max] (the enum's values in order).
#define vtkGLOptionEnumMacro(name, field, min, max)                                         \
  virtual void Set##name(int _arg) {                                                        \
    vtkGLAssignOption(this, this->Options.field,                                            \
                      static_cast<decltype(this->Options.field)>(                           \
                          std::clamp(_arg, static_cast<int>(min), static_cast<int>(max)))); \
  }                                                                                         \
  virtual int Get##name() {                                                                 \
    return static_cast<int>(this->Options.field);                                           \
  }

/// A bool option as a VTK boolean property: Set##name(vtkTypeBool), Get##name, name##On/Off.
#define vtkGLOptionBooleanMacro(name, field)                 \
  virtual void Set##name(vtkTypeBool _arg) {                 \
    vtkGLAssignOption(this, this->Options.field, _arg != 0); \
  }                                                          \
  virtual vtkTypeBool Get##name() {                          \
    return this->Options.field ? 1 : 0;                      \
  }                                                          \
  virtual void name##On() {                                  \
    this->Set##name(1);                                      \
  }                                                          \
  virtual void name##Off() {                                 \
    this->Set##name(0);                                      \
  }

#endif
