// PDF documents joined into one with qpdf (export/pdf_merge.h).
#include "export/pdf_merge.h"

#include "model/translate_noop.h"

#include <fmt/format.h>
#include <qpdf/Buffer.hh>
#include <qpdf/QPDF.hh>
#include <qpdf/QPDFPageDocumentHelper.hh>
#include <qpdf/QPDFWriter.hh>

#include <exception>
#include <memory>

namespace taiwa {

Result<std::string> joinPdfs(const std::vector<std::string>& parts)
{
    if (parts.empty()) return Failure{TAIWA_TRANSLATE_NOOP("taiwa::msg", "no PDF to join")};
    if (parts.size() == 1) return parts.front();
    try {
        // Every part stays open until the whole is written: the pages
        // added to the first refer to their objects.
        std::vector<std::unique_ptr<QPDF>> docs;
        for (std::size_t i = 0; i < parts.size(); ++i) {
            auto doc = std::make_unique<QPDF>();
            doc->processMemoryFile(("part " + std::to_string(i + 1)).c_str(), parts[i].data(), parts[i].size());
            docs.push_back(std::move(doc));
        }
        QPDFPageDocumentHelper whole(*docs.front());
        for (std::size_t i = 1; i < docs.size(); ++i)
            for (QPDFPageObjectHelper& page : QPDFPageDocumentHelper(*docs[i]).getAllPages()) whole.addPage(page, false);
        QPDFWriter writer(*docs.front());
        writer.setOutputMemory();
        writer.setDecodeLevel(qpdf_dl_none);  // the pages' streams as the parts have them
        writer.setDeterministicID(true);      // the same sheet, the same bytes
        writer.write();
        const std::shared_ptr<Buffer> out = writer.getBufferSharedPointer();
        return std::string(reinterpret_cast<const char*>(out->getBuffer()), out->getSize());
    } catch (const std::exception& e) {
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "cannot join the sheet's PDF parts: {}"), e.what())};
    }
}

}  // namespace taiwa
