#include "GLXMLFileWriter.h"

#include "common/Error.h"

#include <vtkBase64Utilities.h>
#include <vtkErrorCode.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOutputStream.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <array>
#include <cstring>

namespace {

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
    const unsigned long n =
        vtkBase64Utilities::Encode(in, static_cast<unsigned long>(length), this->Block.data(), 0);
    return static_cast<bool>(this->Stream->write(reinterpret_cast<const char*>(this->Block.data()),
                                                 static_cast<std::streamsize>(n)));
  }

  std::array<unsigned char, 4 * (kBlockBytes / 3)> Block{};
  std::array<unsigned char, 3> Leftover{};
  size_t Pending = 0;
};

vtkStandardNewMacro(BufferedBase64OutputStream);

/// A VTK XML writer whose binary data goes through BufferedBase64OutputStream.
template <class Writer>
class GLBufferedXMLWriter : public Writer {
public:
  vtkTypeMacro(GLBufferedXMLWriter, Writer);
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
  if (vtkUnstructuredGrid::SafeDownCast(data)) {
    return bufferedBase64 ? writeWith<GLBufferedXMLWriter<vtkXMLUnstructuredGridWriter>>(data, file)
                          : writeWith<vtkXMLUnstructuredGridWriter>(data, file);
  }
  if (vtkPolyData::SafeDownCast(data)) {
    return bufferedBase64 ? writeWith<GLBufferedXMLWriter<vtkXMLPolyDataWriter>>(data, file)
                          : writeWith<vtkXMLPolyDataWriter>(data, file);
  }
  throw GeoLatticeError("cannot write a " + std::string(data ? data->GetClassName() : "null") +
                        " to " + file);
}

}  // namespace geolattice
