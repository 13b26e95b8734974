// The STEP module's reader (step_module.h): STEP translation (serialised, see gvm/step.h),
// then solid selection, face records and tessellation. Every Open CASCADE exception
// becomes a Status here.
#include <Standard_OutOfMemory.hxx>
#include <Bnd_Box.hxx>
#include <BRepBndLib.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <Interface_Check.hxx>
#include <Interface_CheckIterator.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TopExp.hxx>
#include <XSControl_WorkSession.hxx>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <mutex>
#include <numbers>

#include "step/step_internal.h"
#include "step/step_module.h"

namespace gvm {
namespace step_internal {
namespace {

// Open CASCADE keeps the STEP translation parameters (xstep.cascade.unit among them) and the
// unit conversion factors in process-wide statics: two translations at once would race on
// them, so they take turns.
std::mutex& translation_mutex() {
  static std::mutex m;
  return m;
}

std::string_view name_of(IFSelect_ReturnStatus s) {
  switch (s) {
    case IFSelect_RetVoid: return "RetVoid (nothing read)";
    case IFSelect_RetDone: return "RetDone";
    case IFSelect_RetError: return "RetError (syntax errors)";
    case IFSelect_RetFail: return "RetFail (the file cannot be parsed)";
    case IFSelect_RetStop: return "RetStop";
  }
  return "unknown";
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

// Open CASCADE's parser reports to standard output, where gvm writes its JSON: its
// messages go nowhere (ours name the problem).
void silence_open_cascade() {
  static std::once_flag once;
  std::call_once(once, [] { Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream)); });
}

}  // namespace

Status cancelled(const std::string& source) { return Status(StatusCode::kCancelled, source + ": reading cancelled"); }

StatusOr<Translated> translate(std::string_view bytes, const std::string& source, const std::stop_token& stop) {
  std::lock_guard lock(translation_mutex());
  silence_open_cascade();
  STEPControl_Reader reader;
  // Set after the reader exists: its constructor registers the STEP parameters.
  if (!Interface_Static::SetCVal("xstep.cascade.unit", "MM"))
    return Internal(source + ": Open CASCADE refused the length unit setting xstep.cascade.unit = MM");
  std::istringstream in{std::string(bytes)};
  IFSelect_ReturnStatus read = reader.ReadStream(source.c_str(), in);
  if (read != IFSelect_RetDone)
    return InvalidArgument(source + ": not a readable STEP file (Open CASCADE's STEP parser returned " +
                           std::string(name_of(read)) + ")");
  Translated t;
  // The parser skips what it cannot read and still answers RetDone.
  Interface_CheckIterator checks = reader.WS()->ModelCheckList(/*complete=*/false);
  for (checks.Start(); checks.More(); checks.Next()) t.damaged_entities += checks.Value()->HasFailed();
  TColStd_SequenceOfAsciiString length, angle, solid_angle;
  reader.FileUnits(length, angle, solid_angle);
  if (!length.IsEmpty()) t.file_unit = lower(length.First().ToCString());
  if (stop.stop_requested()) return cancelled(source);
  Handle(StopOnRequest) progress = new StopOnRequest(stop);
  reader.TransferRoots(progress->Start());
  if (stop.stop_requested()) return cancelled(source);
  t.shape = reader.OneShape();
  if (t.shape.IsNull())
    return InvalidArgument(source + ": the STEP file holds no B-rep geometry Open CASCADE can "
                           "transfer (for example AP242 tessellated-only geometry)");
  return t;
}

double diagonal(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::AddOptimal(shape, box, /*useTriangulation=*/false, /*useShapeTolerance=*/false);
  if (box.IsVoid()) return 0;
  return std::sqrt(box.SquareExtent());
}

}  // namespace step_internal

namespace {

using namespace step_internal;

Status check_options(const StepOptions& o, const std::string& source) {
  if (!(o.linear_deflection >= 0) || !std::isfinite(o.linear_deflection))
    return InvalidArgument(source + ": linear deflection " + std::to_string(o.linear_deflection) +
                           " mm is not a finite value >= 0 (0 picks 0.1% of the part's size)");
  if (!(o.angular_deflection_degrees > 0 && o.angular_deflection_degrees <= 180))
    return InvalidArgument(source + ": angular deflection " +
                           std::to_string(o.angular_deflection_degrees) +
                           " degrees is not in (0, 180]");
  if (o.solid < -1)
    return InvalidArgument(source + ": options.solid = " + std::to_string(o.solid) +
                           " (use -1 for the only solid, or a 0-based solid index)");
  return Status::Ok();
}

StatusOr<StepPart> read_checked(std::string_view bytes, const StepOptions& options,
                                const std::string& source) {
  auto translated = translate(bytes, source, options.stop);
  if (!translated.ok()) return translated.status();
  auto solid = select_solid(translated->shape, options.solid, source);
  if (!solid.ok()) {
    if (translated->damaged_entities == 0) return solid.status();
    return Status(solid.status().code(),
                  solid.status().message() + " (the STEP parser also found errors in " +
                      std::to_string(translated->damaged_entities) +
                      " entities -- bad syntax or references to missing entities: the file "
                      "looks damaged)");
  }

  StepPart part;
  part.mesh.source = source;
  part.file_unit = translated->file_unit;
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(*solid, TopAbs_FACE, faces);
  if (options.stop.stop_requested()) return cancelled(source);
  if (options.max_triangles > 0 && uint64_t(faces.Extent()) > options.max_triangles) {
    return ResourceExhausted(source + ": " + std::to_string(faces.Extent()) +
                             " B-rep faces (a triangle each at least), more than the limit of " +
                             std::to_string(options.max_triangles) + " faces");
  }
  part.cad_faces = describe_faces(faces);
  if (options.group_holes) part.holes = find_holes(*solid, faces, part.cad_faces);
  part.linear_deflection = options.linear_deflection > 0 ? options.linear_deflection
                                                         : 0.001 * diagonal(*solid);
  if (!(part.linear_deflection > 0))
    return InvalidArgument(source + ": the solid has an empty bounding box");
  part.angular_deflection_degrees = options.angular_deflection_degrees;
  const double angular = options.angular_deflection_degrees * std::numbers::pi / 180;
  if (Status s = tessellate(*solid, part.linear_deflection, angular, options.max_triangles, options.faithful, options.stop, part);
      !s.ok()) {
    return s;
  }
  return part;
}

// Open CASCADE reports failures (corrupt geometry, null handles) by exceptions; a reader of
// untrusted files must turn them into an answer.
StatusOr<StepPart> read_bytes(std::string_view bytes, const StepOptions& options, const std::string& source) {
  if (Status s = check_options(options, source); !s.ok()) return s;
  try {
    return read_checked(bytes, options, source);
  } catch (const Standard_OutOfMemory&) {
    return ResourceExhausted(source + ": out of memory while reading");
  } catch (const std::bad_alloc&) {
    return ResourceExhausted(source + ": out of memory while reading");
  } catch (const Standard_Failure& e) {
    return InvalidArgument(source + ": Open CASCADE failed on this file (" +
                           e.DynamicType()->Name() + ": " + e.GetMessageString() + ")");
  } catch (const std::system_error& e) {
    // A thread (BRepMesh's) that cannot get its stack under the address-space limit.
    if (e.code() == std::errc::resource_unavailable_try_again || e.code() == std::errc::not_enough_memory) {
      return ResourceExhausted(source + ": out of memory while reading");
    }
    return InvalidArgument(source + ": reading failed (" + e.what() + ")");
  } catch (const std::exception& e) {
    // TBB's threads (BRepMesh's) that get no stack say so in a runtime_error.
    if (std::string_view(e.what()).starts_with("pthread_create has failed")) {
      return ResourceExhausted(source + ": out of memory while reading");
    }
    return InvalidArgument(source + ": reading failed (" + e.what() + ")");
  }
}

}  // namespace
}  // namespace gvm

extern "C" __attribute__((visibility("default"))) const gvm::step_internal::StepModule* gvm_step_module() {
  static constexpr gvm::step_internal::StepModule module{&gvm::read_bytes};
  return &module;
}
