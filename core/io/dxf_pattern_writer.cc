#include "core/io/dxf_pattern_writer.h"

#include <dxflib/dl_dxf.h>

#include <iterator>
#include <memory>
#include <stdexcept>
#include <string>

namespace drape {
namespace {

constexpr double kMillimetresPerMetre = 1e3;
const char* const kLayers[] = {"0", "1", "4", "7", "8", "11", "13"};

DL_Attributes On(const char* layer) {
  return DL_Attributes(layer, 256, -1, "BYLAYER", 1.0);
}

void WriteLoop(DL_Dxf& dxf, DL_WriterA& dw, const PieceLine& loop, bool closed, const char* layer) {
  dxf.writePolyline(
      dw, DL_PolylineData(static_cast<int>(loop.size()), 0, 0, closed ? 1 : 0), On(layer));
  for (const PiecePoint& p : loop)
    dxf.writeVertex(dw,
                    DL_VertexData(p[0] * kMillimetresPerMetre, p[1] * kMillimetresPerMetre, 0, 0));
  dxf.writePolylineEnd(dw);
}

void WritePoint(DL_Dxf& dxf, DL_WriterA& dw, const PiecePoint& p, const char* layer) {
  dxf.writePoint(
      dw, DL_PointData(p[0] * kMillimetresPerMetre, p[1] * kMillimetresPerMetre, 0), On(layer));
}

void WriteLine(
    DL_Dxf& dxf, DL_WriterA& dw, const PiecePoint& a, const PiecePoint& b, const char* layer) {
  const double k = kMillimetresPerMetre;
  dxf.writeLine(dw, DL_LineData(a[0] * k, a[1] * k, 0, b[0] * k, b[1] * k, 0), On(layer));
}

void WriteText(DL_Dxf& dxf, DL_WriterA& dw, const std::string& text, const char* layer) {
  dxf.writeText(
      dw, DL_TextData(0, 0, 0, 0, 0, 0, 2.5, 1.0, 0, 0, 0, text, "standard", 0.0), On(layer));
}

void WriteTables(DL_Dxf& dxf, DL_WriterA& dw, const std::vector<PatternPiece>& pieces) {
  dw.sectionTables();
  dxf.writeVPort(dw);
  dw.tableLinetypes(1);
  dxf.writeLinetype(dw, DL_LinetypeData("CONTINUOUS", "Continuous", 0, 0, 0.0));
  dw.tableEnd();
  dw.tableLayers(std::size(kLayers));
  for (const char* layer : kLayers)
    dxf.writeLayer(dw, DL_LayerData(layer, 0), DL_Attributes("", 7, 100, "CONTINUOUS", 1.0));
  dw.tableEnd();
  dw.tableStyle(1);
  dxf.writeStyle(dw, DL_StyleData("standard", 0, 2.5, 1.0, 0.0, 0, 2.5, "txt", ""));
  dw.tableEnd();
  dxf.writeView(dw);
  dxf.writeUcs(dw);
  dw.tableAppid(1);
  dxf.writeAppid(dw, "ACAD");
  dw.tableEnd();
  dxf.writeDimStyle(dw, 1, 1, 1, 1, 1);
  dxf.writeBlockRecord(dw);
  for (const PatternPiece& piece : pieces) dxf.writeBlockRecord(dw, piece.name);
  dw.tableEnd();
  dw.sectionEnd();
}

// A piece's block: the cut line (1), cut-outs (11), notches (4, as points
// on the cut line), the grain line (7), internal lines (8), drill holes
// (13) and the AAMA piece-name text.
void WriteBlock(DL_Dxf& dxf, DL_WriterA& dw, const PatternPiece& piece) {
  dxf.writeBlock(dw, DL_BlockData(piece.name, 0, 0.0, 0.0, 0.0));
  WriteLoop(dxf, dw, piece.boundary, true, "1");
  for (const PieceLine& hole : piece.holes) WriteLoop(dxf, dw, hole, true, "11");
  for (const PiecePoint& p : piece.notches) WritePoint(dxf, dw, p, "4");
  if (piece.grain) WriteLine(dxf, dw, (*piece.grain)[0], (*piece.grain)[1], "7");
  for (const PieceLine& line : piece.internal_lines) {
    if (line.size() == 2)
      WriteLine(dxf, dw, line[0], line[1], "8");
    else if (line.size() > 2)
      WriteLoop(dxf, dw, line, false, "8");
  }
  for (const PiecePoint& p : piece.drills) WritePoint(dxf, dw, p, "13");
  WriteText(dxf, dw, "Piece Name: " + piece.name, "1");
  dxf.writeEndBlock(dw, piece.name);
}

}  // namespace

void WriteDxfPattern(const std::filesystem::path& file, const std::vector<PatternPiece>& pieces) {
  DL_Dxf dxf;
  std::unique_ptr<DL_WriterA> dw(dxf.out(file.string().c_str(), DL_Codes::AC1015));
  if (!dw || dw->openFailed()) throw std::runtime_error("cannot write '" + file.string() + "'");
  dxf.writeHeader(*dw);
  dw->dxfString(9, "$INSUNITS");
  dw->dxfInt(70, 4);  // millimetres
  dw->sectionEnd();
  WriteTables(dxf, *dw, pieces);
  dw->sectionBlocks();
  for (const char* space : {"*Model_Space", "*Paper_Space", "*Paper_Space0"}) {
    dxf.writeBlock(*dw, DL_BlockData(space, 0, 0.0, 0.0, 0.0));
    dxf.writeEndBlock(*dw, space);
  }
  for (const PatternPiece& piece : pieces) WriteBlock(dxf, *dw, piece);
  dw->sectionEnd();
  dw->sectionEntities();
  WriteText(dxf, *dw, "UNITS = METRIC", "1");
  for (const PatternPiece& piece : pieces)
    dxf.writeInsert(*dw, DL_InsertData(piece.name, 0, 0, 0, 1, 1, 1, 0, 1, 1, 0, 0), On("0"));
  dw->sectionEnd();
  dxf.writeObjects(*dw);
  dxf.writeObjectsEnd(*dw);
  dw->dxfEOF();
  dw->close();
}

}  // namespace drape
