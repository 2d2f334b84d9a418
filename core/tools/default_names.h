// The default library's tool names in each language the station speaks,
// made from the tool's figures as the English name is ("Twist drill 10 mm
// carbide 5xD", "超硬ドリル 10 mm 5xD"): one format per kind of name, the
// English one as the tape, the sheet and the command line have always
// read it. A machinist's words: JIS / GB terms, not a word-for-word
// rendering.
#pragma once

#include "model/local_name.h"

#include <fmt/format.h>

#include <string>

namespace taiwa::tools {

struct NameFormat {
    const char* en;
    const char* ja;
    const char* zh;
};

struct Named {
    std::string text;  // English
    LocalNames names;  // "ja", "zh"
};

template <class... Args>
Named named(const NameFormat& f, const Args&... args)
{
    return {fmt::format(fmt::runtime(f.en), args...),
            {{"ja", fmt::format(fmt::runtime(f.ja), args...)}, {"zh", fmt::format(fmt::runtime(f.zh), args...)}}};
}

// The formats, one per kind of name of the default library.
inline constexpr NameFormat kCentreDrill{"Centre drill A{} HSS", "センタドリル A{} ハイス", "中心钻 A{} 高速钢"};
inline constexpr NameFormat kCarbideDrill{"Twist drill {} mm carbide 5xD", "超硬ドリル {} mm 5xD", "硬质合金麻花钻 {} mm 5xD"};
inline constexpr NameFormat kCobaltDrill{"Twist drill {} mm HSS-Co", "コバルトハイスドリル {} mm", "含钴高速钢麻花钻 {} mm"};
inline constexpr NameFormat kFlatEndMill{"Flat end mill {} mm carbide", "超硬スクエアエンドミル {} mm", "硬质合金平底立铣刀 {} mm"};
inline constexpr NameFormat kBallEndMill{"Ball end mill R{} carbide", "超硬ボールエンドミル R{}", "硬质合金球头立铣刀 R{}"};
inline constexpr NameFormat kTaperEndMill{"Taper end mill {} deg/side, tip {} mm", "テーパエンドミル 片角 {}°、先端 {} mm",
                                          "锥度立铣刀 单边 {}°，刀尖 {} mm"};
inline constexpr NameFormat kFaceMill{"Face mill {} mm, {} inserts", "正面フライス {} mm、{} 枚刃", "面铣刀 {} mm，{} 刃"};
inline constexpr NameFormat kTap{"Machine tap M{}x{} HSS-E form C", "ハイスタップ M{}x{} (HSS-E、C 形)", "高速钢机用丝锥 M{}x{}（HSS-E，C 型）"};
inline constexpr NameFormat kReamer{"Machine reamer {} mm H7 carbide", "超硬マシンリーマ {} mm H7", "硬质合金机用铰刀 {} mm H7"};
inline constexpr NameFormat kBoringHead{"Fine boring head set to {} mm", "精密ボーリングヘッド {} mm に設定", "精镗头，调至 {} mm"};
inline constexpr NameFormat kProbe{"Touch probe, {} mm ruby ball", "タッチプローブ、{} mm ルビー球", "测头，{} mm 红宝石测球"};
inline constexpr NameFormat kOdRoughing{"OD roughing {}, {}° holder", "外径荒加工 {}、{}° ホルダ", "外圆粗加工 {}，{}° 刀杆"};
inline constexpr NameFormat kOdFinishing{"OD finishing {}, {}° holder", "外径仕上げ {}、{}° ホルダ", "外圆精加工 {}，{}° 刀杆"};
inline constexpr NameFormat kIdBoring{"ID boring {}, bar Ø{}", "内径ボーリング {}、バー Ø{}", "内孔镗刀 {}，刀杆 Ø{}"};
inline constexpr NameFormat kGrooving{"Grooving blade {} mm, depth {}", "溝入れブレード {} mm、深さ {}", "切槽刀片 {} mm，深度 {}"};
inline constexpr NameFormat kParting{"Parting blade {} mm, up to Ø{}", "突切りブレード {} mm、Ø{} まで", "切断刀片 {} mm，最大 Ø{}"};
inline constexpr NameFormat kThreading{"Threading {}° external, pitch {}-{}", "ねじ切り {}° 外径用、ピッチ {}-{}",
                                       "螺纹车刀 {}° 外螺纹，螺距 {}-{}"};

}  // namespace taiwa::tools
