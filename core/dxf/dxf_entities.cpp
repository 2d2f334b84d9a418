// The one door to dxflib: a creation adapter collecting the entities it
// decodes from the guarded text (dxf_scan.h) into RawEntity.
#include "dxf/dxf_entities.h"

#include <dl_creationadapter.h>
#include <dl_dxf.h>

#include <istream>
#include <optional>
#include <streambuf>

namespace taiwa::dxf::detail {

namespace {

class Collector : public DL_CreationAdapter {
public:
    std::vector<RawEntity> entities;

    void addLine(const DL_LineData& d) override
    {
        RawEntity e = start(RawEntity::Type::Line);
        e.a = {d.x1, d.y1, d.z1};
        e.b = {d.x2, d.y2, d.z2};
        push(std::move(e));
    }
    void addArc(const DL_ArcData& d) override
    {
        RawEntity e = swept(RawEntity::Type::Arc, d);
        e.radius = d.radius;
        push(std::move(e));
    }
    void addCircle(const DL_CircleData& d) override
    {
        RawEntity e = centred(RawEntity::Type::Circle, d);
        e.radius = d.radius;
        push(std::move(e));
    }
    void addEllipse(const DL_EllipseData& d) override
    {
        RawEntity e = swept(RawEntity::Type::Ellipse, d);
        e.b = {d.mx, d.my, d.mz};
        e.radius = d.ratio;
        push(std::move(e));
    }
    void addPolyline(const DL_PolylineData& d) override
    {
        // LWPOLYLINE and POLYLINE both come here: the guard's tag tells which.
        const bool lw = attributes.getLinetype().find("LWPOLYLINE") != std::string::npos;
        RawEntity e = start(lw ? RawEntity::Type::LwPolyline : RawEntity::Type::Polyline);
        e.flags = d.flags;
        pending_ = std::move(e);
    }
    void addVertex(const DL_VertexData& d) override
    {
        if (pending_) pending_->vertices.push_back({d.x, d.y, d.z, d.bulge});
    }
    void addSpline(const DL_SplineData& d) override
    {
        RawEntity e = start(RawEntity::Type::Spline);
        e.flags = d.flags;
        e.degree = static_cast<int>(d.degree);
        e.fitPoints = static_cast<int>(d.nFit);
        pending_ = std::move(e);
    }
    void addControlPoint(const DL_ControlPointData& d) override
    {
        if (pending_) pending_->vertices.push_back({d.x, d.y, d.z, d.w});
    }
    void addKnot(const DL_KnotData& d) override
    {
        if (pending_) pending_->knots.push_back(d.k);
    }
    void endSequence() override { flush(); }
    void endEntity() override { flush(); }

    void finish() { flush(); }

private:
    RawEntity start(RawEntity::Type type)
    {
        flush();
        RawEntity e;
        e.type = type;
        e.layer = attributes.getLayer();
        const std::string tag = attributes.getLinetype();  // "@57 LINE": the guard's tag
        if (tag.size() > 1 && tag[0] == '@') e.line = std::atoi(tag.c_str() + 1);
        if (const DL_Extrusion* x = getExtrusion()) {
            const double* n = x->getDirection();
            e.extrusion = {n[0], n[1], n[2]};
        }
        return e;
    }
    // An entity about a centre (arc, circle, ellipse), its centre set.
    template <class Data>
    RawEntity centred(RawEntity::Type type, const Data& d)
    {
        RawEntity e = start(type);
        e.a = {d.cx, d.cy, d.cz};
        return e;
    }
    // ... and swept from angle1 to angle2 (arc, ellipse).
    template <class Data>
    RawEntity swept(RawEntity::Type type, const Data& d)
    {
        RawEntity e = centred(type, d);
        e.angle1 = d.angle1;
        e.angle2 = d.angle2;
        return e;
    }
    void push(RawEntity e) { entities.push_back(std::move(e)); }
    void flush()
    {
        if (pending_) entities.push_back(std::move(*pending_));
        pending_.reset();
    }

    std::optional<RawEntity> pending_;
};

}  // namespace

namespace {

// The guarded text as dxflib's input stream, read where it lies (a copy of
// a 16 MB drawing in a stringstream cost its pages again).
class TextBuffer : public std::streambuf {
public:
    explicit TextBuffer(const std::string& text)
    {
        char* begin = const_cast<char*>(text.data());  // read only: the get area is never written
        setg(begin, begin, begin + text.size());
    }
};

}  // namespace

std::vector<RawEntity> decodeEntities(const std::string& guardedText, std::size_t count)
{
    Collector c;
    c.entities.reserve(count);
    TextBuffer buffer(guardedText);
    std::istream stream(&buffer);
    DL_Dxf dxf;
    dxf.in(stream, &c);
    c.finish();
    return std::move(c.entities);
}

}  // namespace taiwa::dxf::detail
