#include "GLXMLFileWriter.h"

#include "common/Error.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkErrorCode.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationDoubleVectorKey.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOutputStream.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <array>
#include <cmath>
#include <cstring>

namespace {

/// RFC 4648 base64 of `length` bytes into `out` ('=' padding for a last 1 or 2 bytes), the
/// characters vtkBase64Utilities::Encode writes; returns their count. Here because Debian's
/// vtkBase64Utilities runs unoptimized (a function call and an assert per character: half of the
/// time of writing a toolpath file; bench_files BM_WriteToolpathFile).
size_t encodeBase64(const unsigned char* in, size_t length, unsigned char* out) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  unsigned char* o = out;
  size_t i = 0;
  for (; i + 3 <= length; i += 3) {
    const unsigned v = (unsigned{in[i]} << 16) | (unsigned{in[i + 1]} << 8) | in[i + 2];
    *o++ = kAlphabet[v >> 18];
    *o++ = kAlphabet[(v >> 12) & 63];
    *o++ = kAlphabet[(v >> 6) & 63];
    *o++ = kAlphabet[v & 63];
  }
  if (i < length) {
    const bool two = i + 1 < length;
    const unsigned v = (unsigned{in[i]} << 16) | (two ? unsigned{in[i + 1]} << 8 : 0u);
    *o++ = kAlphabet[v >> 18];
    *o++ = kAlphabet[(v >> 12) & 63];
    *o++ = two ? kAlphabet[(v >> 6) & 63] : '=';
    *o++ = '=';
  }
  return static_cast<size_t>(o - out);
}

/// Base64 like vtkBase64OutputStream (one encoding from StartWriting to EndWriting, '=' padding
/// at the end), written to the stream in blocks.
class BufferedBase64OutputStream : public vtkOutputStream {
public:
  vtkTypeMacro(BufferedBase64OutputStream, vtkOutputStream);
  static BufferedBase64OutputStream* New();

  int StartWriting() override {
    this->Pending = 0;
    return this->vtkOutputStream::StartWriting();
  }

  int Write(void const* data, size_t length) override {
    const auto* in = static_cast<const unsigned char*>(data);
    // Complete the triplet the last call left open.
    while (this->Pending > 0 && length > 0) {
      this->Leftover[this->Pending++] = *in++;
      --length;
      if (this->Pending == 3) {
        this->Pending = 0;
        if (!this->Encode(this->Leftover.data(), 3)) {
          return 0;
        }
      }
    }
    const size_t whole = length - length % 3;
    for (size_t done = 0; done < whole; done += kBlockBytes) {
      if (!this->Encode(in + done, std::min(kBlockBytes, whole - done))) {
        return 0;
      }
    }
    for (size_t i = whole; i < length; ++i) {
      this->Leftover[this->Pending++] = in[i];
    }
    return 1;
  }

  int EndWriting() override {
    const size_t pending = this->Pending;
    this->Pending = 0;
    return pending == 0 || this->Encode(this->Leftover.data(), pending) ? 1 : 0;
  }

protected:
  BufferedBase64OutputStream() = default;
  ~BufferedBase64OutputStream() override = default;

private:
  static constexpr size_t kBlockBytes = 3 * 16384;  ///< input bytes per block: 64 KiB encoded

  /// Encodes length bytes (a multiple of 3, or the last 1-2 bytes: padded) and writes them.
  bool Encode(const unsigned char* in, size_t length) {
    const size_t n = encodeBase64(in, length, this->Block.data());
    return static_cast<bool>(this->Stream->write(reinterpret_cast<const char*>(this->Block.data()),
                                                 static_cast<std::streamsize>(n)));
  }

  std::array<unsigned char, 4 * (kBlockBytes / 3)> Block{};
  std::array<unsigned char, 3> Leftover{};
  size_t Pending = 0;
};

vtkStandardNewMacro(BufferedBase64OutputStream);

/// A VTK XML writer that frees its appended-mode position arrays only when it allocated them.
/// VTK 9.2's writers free them when a write fails for lack of disk space (WriteAPiece), also in
/// binary inline mode, which never allocates them: the process aborted ("munmap_chunk(): invalid
/// pointer", "double free or corruption") instead of reporting the failure.
template <class Writer>
class GLXMLWriter : public Writer {
public:
  vtkTypeMacro(GLXMLWriter, Writer);
  static GLXMLWriter* New() {
    auto* writer = new GLXMLWriter;
    writer->InitializeObjectBase();
    return writer;
  }

protected:
  GLXMLWriter() = default;
  ~GLXMLWriter() override = default;
  void AllocatePositionArrays() override {
    this->Writer::AllocatePositionArrays();
    this->PositionArraysAllocated = true;
  }
  void DeletePositionArrays() override {
    if (this->PositionArraysAllocated) {
      this->Writer::DeletePositionArrays();
      this->PositionArraysAllocated = false;
    }
  }

private:
  bool PositionArraysAllocated = false;
};

/// A VTK XML writer whose binary data goes through BufferedBase64OutputStream.
template <class Writer>
class GLBufferedXMLWriter : public GLXMLWriter<Writer> {
public:
  vtkTypeMacro(GLBufferedXMLWriter, GLXMLWriter<Writer>);
  static GLBufferedXMLWriter* New() {
    auto* writer = new GLBufferedXMLWriter;
    writer->InitializeObjectBase();
    return writer;
  }

protected:
  GLBufferedXMLWriter() {
    vtkNew<BufferedBase64OutputStream> stream;
    this->SetDataStream(stream);
  }
  ~GLBufferedXMLWriter() override = default;
};

/// The range VTK's XML writers put in a one-component array's header (RangeMin, RangeMax),
/// NaN values left out as vtkDataArray leaves them out.
template <class T>
void valueRange(const T* values, vtkIdType count, double range[2]) {
  double lo = VTK_DOUBLE_MAX, hi = VTK_DOUBLE_MIN;
  for (vtkIdType i = 0; i < count; ++i) {
    const double x = static_cast<double>(values[i]);
    if (!std::isnan(x)) {
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
  }
  range[0] = lo;
  range[1] = hi;
}

/// VTK's XML writers compute each array's range for its header with vtkDataArray::GetRange, at
/// 12-18 ns per value (measured: 5 % of topopt's whole run). For a one-component array the same
/// numbers in one typed pass, stored where GetRange looks first (the per-component range, newer
/// than the array), so the writer takes them. A multi-component array's range (of its tuples'
/// L2 norm) is left to VTK: its key is one the writer would copy into the file. So are arrays
/// that are not contiguous or empty; the file is the same either way.
void cacheRange(vtkDataArray* array) {
  if (!array || array->GetNumberOfComponents() != 1 || !array->HasStandardMemoryLayout() ||
      array->GetNumberOfTuples() == 0) {
    return;
  }
  double range[2];
  switch (array->GetDataType()) {
    vtkTemplateMacro(valueRange(static_cast<const VTK_TT*>(array->GetVoidPointer(0)),
                                array->GetNumberOfTuples(), range));
    default:
      return;
  }
  vtkInformation* info = array->GetInformation();
  vtkInformationVector* perComponent = info->Get(vtkDataArray::PER_COMPONENT());
  if (!perComponent) {
    vtkNew<vtkInformationVector> created;
    info->Set(vtkDataArray::PER_COMPONENT(), created);
    perComponent = created;
  }
  if (perComponent->GetNumberOfInformationObjects() < 1) {
    perComponent->SetNumberOfInformationObjects(1);
  }
  perComponent->GetInformationObject(0)->Set(vtkDataArray::COMPONENT_RANGE(), range, 2);
}

void cacheRanges(vtkFieldData* arrays) {
  for (int i = 0; arrays && i < arrays->GetNumberOfArrays(); ++i) {
    cacheRange(arrays->GetArray(i));
  }
}

void cacheRanges(vtkDataObject* data) {
  cacheRanges(data->GetFieldData());
  if (auto* set = vtkPointSet::SafeDownCast(data)) {  // (its points have three components)
    cacheRanges(set->GetPointData());
    cacheRanges(set->GetCellData());
  }
}

template <class Writer>
bool writeWith(vtkDataObject* data, const std::string& file) {
  vtkNew<Writer> writer;
  writer->SetInputData(data);
  writer->SetDataModeToBinary();
  writer->SetCompressorTypeToLZ4();
  writer->SetFileName(file.c_str());
  writer->Write();  // returns 1 even when the file cannot be opened: the error code tells
  return writer->GetErrorCode() == vtkErrorCode::NoError;
}

}  // namespace

namespace geolattice {

bool writeXmlDataFile(vtkDataObject* data, const std::string& file, bool bufferedBase64) {
  if (bufferedBase64 &&
      (vtkUnstructuredGrid::SafeDownCast(data) || vtkPolyData::SafeDownCast(data))) {
    cacheRanges(data);
  }
  if (vtkUnstructuredGrid::SafeDownCast(data)) {
    return bufferedBase64 ? writeWith<GLBufferedXMLWriter<vtkXMLUnstructuredGridWriter>>(data, file)
                          : writeWith<GLXMLWriter<vtkXMLUnstructuredGridWriter>>(data, file);
  }
  if (vtkPolyData::SafeDownCast(data)) {
    return bufferedBase64 ? writeWith<GLBufferedXMLWriter<vtkXMLPolyDataWriter>>(data, file)
                          : writeWith<GLXMLWriter<vtkXMLPolyDataWriter>>(data, file);
  }
  throw GeoLatticeError("cannot write a " + std::string(data ? data->GetClassName() : "null") +
                        " to " + file);
}

}  // namespace geolattice
