<?xml version="1.0" encoding="utf-8"?>
<!-- Japanese texts of the station window (lupdate from ui/, translated by hand); compiled to taiwa_ja.qm by lrelease at build time. -->
<!DOCTYPE TS>
<TS version="2.1" language="ja_JP">
<context>
    <name>taiwa::ui::FileActions</name>
    <message>
        <location filename="../../ui/file_actions.cpp" line="38"/>
        <source>Unsaved changes</source>
        <translation>未保存の変更</translation>
    </message>
    <message>
        <location filename="../../ui/file_actions.cpp" line="39"/>
        <source>The job has unsaved changes. Save them?</source>
        <translation>ジョブに未保存の変更があります。保存しますか?</translation>
    </message>
    <message>
        <location filename="../../ui/file_actions.cpp" line="50"/>
        <source>New job</source>
        <translation>新規ジョブ</translation>
    </message>
    <message>
        <location filename="../../ui/file_actions.cpp" line="58"/>
        <source>Open job</source>
        <translation>ジョブを開く</translation>
    </message>
    <message>
        <location filename="../../ui/file_actions.cpp" line="69"/>
        <source>Cannot open job</source>
        <translation>ジョブを開けません</translation>
    </message>
    <message>
        <location filename="../../ui/file_actions.cpp" line="75"/>
        <source>Opened %1</source>
        <translation>%1 を開きました</translation>
    </message>
    <message>
        <location filename="../../ui/file_actions.cpp" line="83"/>
        <source>Save job</source>
        <translation>ジョブを保存</translation>
    </message>
    <message>
        <location filename="../../ui/file_actions.cpp" line="94"/>
        <source>Cannot save job</source>
        <translation>ジョブを保存できません</translation>
    </message>
    <message>
        <location filename="../../ui/file_actions.cpp" line="98"/>
        <source>Saved %1</source>
        <translation>%1 を保存しました</translation>
    </message>
    <message>
        <location filename="../../ui/file_actions.cpp" line="107"/>
        <location filename="../../ui/file_actions.cpp" line="115"/>
        <source>Export</source>
        <translation>出力</translation>
    </message>
    <message>
        <location filename="../../ui/file_actions.cpp" line="107"/>
        <source>The job has input errors; fix them before exporting.</source>
        <translation>ジョブに入力エラーがあります。出力する前に修正してください。</translation>
    </message>
    <message>
        <location filename="../../ui/file_actions.cpp" line="110"/>
        <source>Export into folder</source>
        <translation>出力先フォルダ</translation>
    </message>
    <message>
        <location filename="../../ui/file_actions.cpp" line="115"/>
        <source>Controller dialect</source>
        <translation>制御装置の方言</translation>
    </message>
    <message>
        <location filename="../../ui/file_actions.cpp" line="124"/>
        <source>Export failed</source>
        <translation>出力に失敗しました</translation>
    </message>
    <message>
        <location filename="../../ui/file_actions.cpp" line="125"/>
        <source>Exported %1 files into %2</source>
        <translation>%1 個のファイルを %2 に出力しました</translation>
    </message>
    <message>
        <location filename="../../ui/file_actions.cpp" line="133"/>
        <source>an untitled job</source>
        <translation>無題のジョブ</translation>
    </message>
    <message>
        <location filename="../../ui/file_actions.cpp" line="135"/>
        <source>Recover job</source>
        <translation>ジョブの復元</translation>
    </message>
    <message>
        <location filename="../../ui/file_actions.cpp" line="136"/>
        <source>Taiwa was not closed properly while editing %1. Its autosaved copy is newer than the file. Restore the autosaved copy?</source>
        <translation>%1 の編集中に Taiwa が正しく終了しませんでした。自動保存のコピーがファイルより新しいです。自動保存のコピーを復元しますか?</translation>
    </message>
    <message>
        <location filename="../../ui/file_actions.cpp" line="145"/>
        <source>Restored the autosaved job (not saved to a file yet)</source>
        <translation>自動保存のジョブを復元しました(まだファイルには保存されていません)</translation>
    </message>
    <message>
        <location filename="../../ui/file_actions.cpp" line="168"/>
        <source>(none)</source>
        <translation>(なし)</translation>
    </message>
</context>
<context>
    <name>taiwa::ui::JobProperties</name>
    <message>
        <location filename="../../ui/job_properties.cpp" line="36"/>
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <location filename="../../ui/job_properties.cpp" line="37"/>
        <source>inch (converts every length)</source>
        <translation>インチ(全ての長さを換算)</translation>
    </message>
    <message>
        <location filename="../../ui/job_properties.cpp" line="38"/>
        <source>Name</source>
        <translation>名前</translation>
    </message>
    <message>
        <location filename="../../ui/job_properties.cpp" line="39"/>
        <source>Material</source>
        <translation>材質</translation>
    </message>
    <message>
        <location filename="../../ui/job_properties.cpp" line="40"/>
        <source>Units</source>
        <translation>単位</translation>
    </message>
    <message>
        <location filename="../../ui/job_properties.cpp" line="41"/>
        <source>Stock width (X)</source>
        <translation>素材の幅 (X)</translation>
    </message>
    <message>
        <location filename="../../ui/job_properties.cpp" line="41"/>
        <source>Stock length (Y)</source>
        <translation>素材の長さ (Y)</translation>
    </message>
    <message>
        <location filename="../../ui/job_properties.cpp" line="41"/>
        <source>Stock height (Z)</source>
        <translation>素材の高さ (Z)</translation>
    </message>
    <message>
        <location filename="../../ui/job_properties.cpp" line="54"/>
        <source>Edit job name</source>
        <translation>ジョブ名の編集</translation>
    </message>
    <message>
        <location filename="../../ui/job_properties.cpp" line="59"/>
        <source>Change material</source>
        <translation>材質の変更</translation>
    </message>
    <message>
        <location filename="../../ui/job_properties.cpp" line="63"/>
        <source>Change length unit</source>
        <translation>単位の変更</translation>
    </message>
    <message>
        <location filename="../../ui/job_properties.cpp" line="73"/>
        <location filename="../../ui/job_properties.cpp" line="104"/>
        <source>not a number</source>
        <translation>数値ではありません</translation>
    </message>
    <message>
        <location filename="../../ui/job_properties.cpp" line="78"/>
        <source>Edit %1</source>
        <translation>%1 の編集</translation>
    </message>
    <message>
        <location filename="../../ui/job_properties.cpp" line="87"/>
        <source> (unknown)</source>
        <translation>(不明)</translation>
    </message>
</context>
<context>
    <name>taiwa::ui::ModulePalette</name>
    <message>
        <location filename="../../ui/module_palette.cpp" line="28"/>
        <source>Add M4 pocket</source>
        <translation>M4 ポケットを追加</translation>
    </message>
    <message>
        <location filename="../../ui/module_palette.cpp" line="28"/>
        <source>Add M2D 3-D pocket</source>
        <translation>M2D 立体ポケットを追加</translation>
    </message>
    <message>
        <source>Add work-centre probing</source>
        <translation>ワーク中心の測定を追加</translation>
    </message>
</context>
<context>
    <name>taiwa::ui::NcView</name>
    <message>
        <location filename="../../ui/nc_view.cpp" line="29"/>
        <source>&amp;NC program, dialect:</source>
        <translation>NC プログラム(&amp;N)、方言:</translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/nc_view.cpp" line="51"/>
        <source>%n block(s)</source>
        <translation>
            <numerusform>%n ブロック</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>taiwa::ui::PlanRunner</name>
    <message>
        <location filename="../../ui/plan_runner.cpp" line="79"/>
        <source>(no program: the job has input errors)</source>
        <translation>(プログラムなし: ジョブに入力エラーがあります)</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <location filename="../../ui/plan_runner.cpp" line="23"/>
        <source>(no program: the job has input errors)</source>
        <translation>(プログラムなし: ジョブに入力エラーがあります)</translation>
    </message>
    <message>
        <location filename="../../ui/plan_runner.cpp" line="36"/>
        <source>(no program: %1)</source>
        <translation>(プログラムなし: %1)</translation>
    </message>
</context>
<context>
    <name>taiwa::ui::StationWindow</name>
    <message>
        <source>Technology data…</source>
        <translation>加工技術データ…</translation>
    </message>
    <message>
        <source>Tool library…</source>
        <translation>工具ライブラリ…</translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="59"/>
        <source>Tool library: %1 (using the built-in library)</source>
        <translation>工具ライブラリ: %1(内蔵ライブラリを使用)</translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="70"/>
        <source>Modules</source>
        <translation>モジュール</translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="72"/>
        <source>Machining units, in order</source>
        <translation>加工ユニット(加工順)</translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="74"/>
        <source>Job</source>
        <translation>ジョブ</translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="84"/>
        <source>Pick a module on the left (M4 or M2D) to add a machining unit.</source>
        <translation>左のモジュール(M4 または M2D)を選んで加工ユニットを追加してください。</translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="93"/>
        <source>Unit</source>
        <translation>ユニット</translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="114"/>
        <source>No 3-D preview: this display has no OpenGL.</source>
        <translation>3D プレビューなし: このディスプレイは OpenGL を使えません。</translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="132"/>
        <source>&amp;File</source>
        <translation>ファイル(&amp;F)</translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="133"/>
        <source>&amp;New</source>
        <translation>新規(&amp;N)</translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="134"/>
        <source>&amp;Open…</source>
        <translation>開く(&amp;O)…</translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="135"/>
        <source>Open &amp;recent</source>
        <translation>最近使ったファイル(&amp;R)</translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="137"/>
        <source>&amp;Save</source>
        <translation>保存(&amp;S)</translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="138"/>
        <source>Save &amp;as…</source>
        <translation>名前を付けて保存(&amp;A)…</translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="140"/>
        <source>&amp;Export tape and sheet…</source>
        <translation>テープと作業指示書を出力(&amp;E)…</translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="140"/>
        <source>Ctrl+E</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="142"/>
        <source>&amp;Quit</source>
        <translation>終了(&amp;Q)</translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="144"/>
        <source>&amp;Edit</source>
        <translation>編集(&amp;E)</translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="145"/>
        <source>&amp;Undo</source>
        <translation>元に戻す(&amp;U)</translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="147"/>
        <source>&amp;Redo</source>
        <translation>やり直し(&amp;R)</translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="148"/>
        <source>Ctrl+Shift+Z</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="148"/>
        <source>Ctrl+Y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="152"/>
        <source>&amp;Job</source>
        <translation>ジョブ(&amp;J)</translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="153"/>
        <source>Add &amp;M4 pocket</source>
        <translation>M4 ポケットを追加(&amp;M)</translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="153"/>
        <source>Ctrl+4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="154"/>
        <source>Add M&amp;2D pocket</source>
        <translation>M2D ポケットを追加(&amp;2)</translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="154"/>
        <source>Ctrl+3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="156"/>
        <source>&amp;Technology data…</source>
        <translation>加工技術データ(&amp;T)…</translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="156"/>
        <source>Ctrl+T</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="157"/>
        <source>Tool &amp;library…</source>
        <translation>工具ライブラリ(&amp;L)…</translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="157"/>
        <source>Ctrl+L</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="159"/>
        <source>&amp;View</source>
        <translation>表示(&amp;V)</translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="160"/>
        <source>&amp;Language</source>
        <translation>言語(&amp;L)</translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="169"/>
        <source>The language changes when Taiwa is started again.</source>
        <translation>言語は Taiwa の次回起動時に切り替わります。</translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="251"/>
        <source>Edit %1 of unit %2</source>
        <translation>ユニット %2 の %1 を編集</translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/station_window.cpp" line="280"/>
        <source>%n problem(s) in other units</source>
        <translation>
            <numerusform>他のユニットに %n 件の問題</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="291"/>
        <source>Edit technology data</source>
        <translation>加工技術データの編集</translation>
    </message>
    <message>
        <location filename="../../ui/station_window.cpp" line="305"/>
        <source>untitled</source>
        <translation>無題</translation>
    </message>
    <message>
        <source>Stock &amp;grid</source>
        <translation>素材グリッド(&amp;G)</translation>
    </message>
    <message>
        <source>Fine: %1 mm, up to %2 cells</source>
        <translation>細かい: %1 mm、最大 %2 セル</translation>
    </message>
    <message>
        <source>Standard: %1 mm, up to %2 cells</source>
        <translation>標準: %1 mm、最大 %2 セル</translation>
    </message>
    <message>
        <source>Coarse: %1 mm, up to %2 cells</source>
        <translation>粗い: %1 mm、最大 %2 セル</translation>
    </message>
    <message>
        <source>Stock grid: %1 mm cells on this stock</source>
        <translation>素材グリッド: この素材では %1 mm のセル</translation>
    </message>
</context>
<context>
    <name>taiwa::ui::StepPanel</name>
    <message>
        <location filename="../../ui/step_panel.cpp" line="28"/>
        <source>&amp;Stock</source>
        <translation>素材(&amp;S)</translation>
    </message>
    <message>
        <source>&amp;Before step</source>
        <translation>加工前(&amp;B)</translation>
    </message>
    <message>
        <source>The stock as the simulation cuts it, instead of a glass block</source>
        <translation>ガラスのブロックではなく、シミュレーションで削った素材を表示</translation>
    </message>
    <message>
        <source>The stock as it is before the selected step, instead of after it</source>
        <translation>選んだ工程の後ではなく、その前の素材を表示</translation>
    </message>
    <message>
        <location filename="../../ui/step_panel.cpp" line="37"/>
        <location filename="../../ui/step_panel.cpp" line="116"/>
        <source>▶ Pla&amp;y</source>
        <translation>▶ 再生(&amp;Y)</translation>
    </message>
    <message>
        <location filename="../../ui/step_panel.cpp" line="43"/>
        <source>&amp;All steps</source>
        <translation>全工程(&amp;A)</translation>
    </message>
    <message>
        <location filename="../../ui/step_panel.cpp" line="49"/>
        <source>&amp;Iso</source>
        <translation>等角(&amp;I)</translation>
    </message>
    <message>
        <location filename="../../ui/step_panel.cpp" line="49"/>
        <source>&amp;Top</source>
        <translation>上面(&amp;T)</translation>
    </message>
    <message>
        <location filename="../../ui/step_panel.cpp" line="49"/>
        <source>F&amp;ront</source>
        <translation>正面(&amp;R)</translation>
    </message>
    <message>
        <location filename="../../ui/step_panel.cpp" line="116"/>
        <source>■ Stop (&amp;Y)</source>
        <translation>■ 停止(&amp;Y)</translation>
    </message>
    <message>
        <location filename="../../ui/step_panel.cpp" line="144"/>
        <source>No steps: the job has input errors.</source>
        <translation>工程なし: ジョブに入力エラーがあります。</translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/step_panel.cpp" line="146"/>
        <source>%n step(s), %1 min, %2 tool change(s)</source>
        <translation>
            <numerusform>%n 工程、%1 分、工具交換 %2 回</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../../ui/step_panel.cpp" line="154"/>
        <source>&lt;b&gt;%1&lt;/b&gt; of unit %2 (%3), machining type %4</source>
        <translation>ユニット %2 (%3) の &lt;b&gt;%1&lt;/b&gt;、加工種別コード %4</translation>
    </message>
    <message>
        <location filename="../../ui/step_panel.cpp" line="159"/>
        <source>Air to %1, cuts to %2; leaves wall %3, floor %4</source>
        <translation>%1 まで空送り、%2 まで切削; 残し代 壁 %3、底 %4</translation>
    </message>
    <message>
        <location filename="../../ui/step_panel.cpp" line="167"/>
        <source>Outline %1, r %2</source>
        <translation>輪郭 %1、r %2</translation>
    </message>
    <message>
        <location filename="../../ui/step_panel.cpp" line="169"/>
        <source>Inclined face at %1° from the vertical, scallop %2</source>
        <translation>傾斜面 垂直から %1°、カスプ高さ %2</translation>
    </message>
    <message>
        <location filename="../../ui/step_panel.cpp" line="172"/>
        <source>At (%1, %2), Ø %3</source>
        <translation>位置 (%1, %2)、Ø %3</translation>
    </message>
    <message>
        <location filename="../../ui/step_panel.cpp" line="176"/>
        <source>Wall taper %1° per side</source>
        <translation>壁テーパ 片側 %1°</translation>
    </message>
    <message>
        <location filename="../../ui/step_panel.cpp" line="179"/>
        <source>T%1 %2: %3</source>
        <translation>T%1 %2: %3</translation>
    </message>
    <message>
        <location filename="../../ui/step_panel.cpp" line="184"/>
        <source>Estimated %1 min</source>
        <translation>予想 %1 分</translation>
    </message>
</context>
<context>
    <name>taiwa::ui::StepTable</name>
    <message>
        <location filename="../../ui/step_table.cpp" line="15"/>
        <source>No.</source>
        <translation>No.</translation>
    </message>
    <message>
        <location filename="../../ui/step_table.cpp" line="15"/>
        <source>Unit</source>
        <translation>ユニット</translation>
    </message>
    <message>
        <location filename="../../ui/step_table.cpp" line="15"/>
        <source>Step</source>
        <translation>工程</translation>
    </message>
    <message>
        <location filename="../../ui/step_table.cpp" line="15"/>
        <source>Tool</source>
        <translation>工具</translation>
    </message>
    <message>
        <location filename="../../ui/step_table.cpp" line="15"/>
        <source>Start</source>
        <translation>開始深さ</translation>
    </message>
    <message>
        <location filename="../../ui/step_table.cpp" line="15"/>
        <source>Depth</source>
        <translation>深さ</translation>
    </message>
    <message>
        <location filename="../../ui/step_table.cpp" line="15"/>
        <source>Time</source>
        <translation>時間</translation>
    </message>
</context>
<context>
    <name>taiwa::ui::TechnologyDialog</name>
    <message>
        <location filename="../../ui/technology_dialog.cpp" line="48"/>
        <source>Technology data</source>
        <translation>加工技術データ</translation>
    </message>
    <message>
        <location filename="../../ui/technology_dialog.cpp" line="52"/>
        <source>&lt;b&gt;Value&lt;/b&gt;</source>
        <translation>&lt;b&gt;項目&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../../ui/technology_dialog.cpp" line="53"/>
        <source>&lt;b&gt;Table (%1)&lt;/b&gt;</source>
        <translation>&lt;b&gt;テーブル (%1)&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../../ui/technology_dialog.cpp" line="54"/>
        <source>&lt;b&gt;This job&lt;/b&gt; (empty = table)</source>
        <translation>&lt;b&gt;このジョブ&lt;/b&gt;(空欄 = テーブル)</translation>
    </message>
    <message>
        <location filename="../../ui/technology_dialog.cpp" line="55"/>
        <source>&lt;b&gt;In force&lt;/b&gt;</source>
        <translation>&lt;b&gt;適用値&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../../ui/technology_dialog.cpp" line="62"/>
        <source>(unknown material)</source>
        <translation>(不明な材質)</translation>
    </message>
    <message>
        <location filename="../../ui/technology_dialog.cpp" line="107"/>
        <source>not a number</source>
        <translation>数値ではありません</translation>
    </message>
</context>
<context>
    <name>taiwa::ui::ToolLibraryDialog</name>
    <message>
        <location filename="../../ui/tool_library_dialog.cpp" line="24"/>
        <source>&amp;Reset wear of the selected tool</source>
        <translation>選択した工具の摩耗をリセット(&amp;R)</translation>
    </message>
    <message>
        <location filename="../../ui/tool_library_dialog.cpp" line="26"/>
        <source>Tool library</source>
        <translation>工具ライブラリ</translation>
    </message>
    <message>
        <location filename="../../ui/tool_library_dialog.cpp" line="29"/>
        <source>T</source>
        <translation>T</translation>
    </message>
    <message>
        <location filename="../../ui/tool_library_dialog.cpp" line="29"/>
        <source>Name</source>
        <translation>名前</translation>
    </message>
    <message>
        <location filename="../../ui/tool_library_dialog.cpp" line="29"/>
        <source>Type</source>
        <translation>種類</translation>
    </message>
    <message>
        <location filename="../../ui/tool_library_dialog.cpp" line="29"/>
        <source>Ø mm</source>
        <translation>Ø mm</translation>
    </message>
    <message>
        <location filename="../../ui/tool_library_dialog.cpp" line="29"/>
        <source>Corner r</source>
        <translation>コーナ r</translation>
    </message>
    <message>
        <location filename="../../ui/tool_library_dialog.cpp" line="29"/>
        <source>Taper °</source>
        <translation>テーパ °</translation>
    </message>
    <message>
        <location filename="../../ui/tool_library_dialog.cpp" line="30"/>
        <source>Flute mm</source>
        <translation>刃長 mm</translation>
    </message>
    <message>
        <location filename="../../ui/tool_library_dialog.cpp" line="30"/>
        <source>Holder</source>
        <translation>ホルダ</translation>
    </message>
    <message>
        <location filename="../../ui/tool_library_dialog.cpp" line="30"/>
        <source>Life min</source>
        <translation>寿命 分</translation>
    </message>
    <message>
        <location filename="../../ui/tool_library_dialog.cpp" line="30"/>
        <source>Used min</source>
        <translation>使用 分</translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/tool_library_dialog.cpp" line="61"/>
        <source>%1 — %n tool(s)</source>
        <translation>
            <numerusform>%1 — %n 本の工具</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../../ui/tool_library_dialog.cpp" line="62"/>
        <source>Cannot read the tool library: %1</source>
        <translation>工具ライブラリを読めません: %1</translation>
    </message>
    <message>
        <location filename="../../ui/tool_library_dialog.cpp" line="87"/>
        <source>Select a tool first.</source>
        <translation>先に工具を選んでください。</translation>
    </message>
    <message>
        <location filename="../../ui/tool_library_dialog.cpp" line="95"/>
        <source>Cannot save the tool: %1</source>
        <translation>工具を保存できません: %1</translation>
    </message>
</context>
<context>
    <name>taiwa::ui::UnitForm</name>
    <message>
        <location filename="../../ui/unit_form.cpp" line="122"/>
        <location filename="../../ui/unit_form.cpp" line="159"/>
        <source>not a number</source>
        <translation>数値ではありません</translation>
    </message>
</context>
<context>
    <name>taiwa::ui::UnitListPanel</name>
    <message>
        <location filename="../../ui/unit_list_panel.cpp" line="28"/>
        <source>D&amp;uplicate</source>
        <translation>複製(&amp;U)</translation>
    </message>
    <message>
        <location filename="../../ui/unit_list_panel.cpp" line="29"/>
        <source>▲ U&amp;p</source>
        <translation>▲ 上へ(&amp;P)</translation>
    </message>
    <message>
        <location filename="../../ui/unit_list_panel.cpp" line="30"/>
        <source>▼ Do&amp;wn</source>
        <translation>▼ 下へ(&amp;W)</translation>
    </message>
    <message>
        <location filename="../../ui/unit_list_panel.cpp" line="31"/>
        <source>De&amp;lete</source>
        <translation>削除(&amp;L)</translation>
    </message>
    <message>
        <location filename="../../ui/unit_list_panel.cpp" line="68"/>
        <source>Add M4 unit</source>
        <translation>M4 ユニットを追加</translation>
    </message>
    <message>
        <location filename="../../ui/unit_list_panel.cpp" line="82"/>
        <source>Add M2D unit</source>
        <translation>M2D ユニットを追加</translation>
    </message>
    <message>
        <location filename="../../ui/unit_list_panel.cpp" line="91"/>
        <source>Duplicate unit %1</source>
        <translation>ユニット %1 を複製</translation>
    </message>
    <message>
        <location filename="../../ui/unit_list_panel.cpp" line="101"/>
        <source>Move unit %1</source>
        <translation>ユニット %1 を移動</translation>
    </message>
    <message>
        <location filename="../../ui/unit_list_panel.cpp" line="110"/>
        <source>Delete unit %1</source>
        <translation>ユニット %1 を削除</translation>
    </message>
</context>
<context>
    <name>taiwa::ui::FieldSpec</name>
    <message>
        <location filename="../../ui/field_spec.cpp" line="64"/>
        <location filename="../../ui/field_spec.cpp" line="112"/>
        <source>r1 (corner radius)</source>
        <translation>r1(コーナ半径)</translation>
    </message>
    <message>
        <location filename="../../ui/field_spec.cpp" line="67"/>
        <location filename="../../ui/field_spec.cpp" line="94"/>
        <source>T (depth)</source>
        <translation>T(深さ)</translation>
    </message>
    <message>
        <location filename="../../ui/field_spec.cpp" line="69"/>
        <source>S (taper, °/side)</source>
        <translation>S(テーパ、片側 °)</translation>
    </message>
    <message>
        <location filename="../../ui/field_spec.cpp" line="71"/>
        <location filename="../../ui/field_spec.cpp" line="115"/>
        <source>U (tool use)</source>
        <translation>U(工具使用区分)</translation>
    </message>
    <message>
        <location filename="../../ui/field_spec.cpp" line="75"/>
        <source>F (wall finish)</source>
        <translation>F(仕上げ区分)</translation>
    </message>
    <message>
        <location filename="../../ui/field_spec.cpp" line="78"/>
        <location filename="../../ui/field_spec.cpp" line="117"/>
        <source>H (pilot hole)</source>
        <translation>H(下穴)</translation>
    </message>
    <message>
        <location filename="../../ui/field_spec.cpp" line="90"/>
        <source>L1 (length X)</source>
        <translation>L1(X 方向長さ)</translation>
    </message>
    <message>
        <location filename="../../ui/field_spec.cpp" line="92"/>
        <source>L2 (length Y)</source>
        <translation>L2(Y 方向長さ)</translation>
    </message>
    <message>
        <location filename="../../ui/field_spec.cpp" line="96"/>
        <source>θ1 (left wall, °)</source>
        <translation>θ1(左壁、°)</translation>
    </message>
    <message>
        <location filename="../../ui/field_spec.cpp" line="101"/>
        <source>θ2 (right wall, °)</source>
        <translation>θ2(右壁、°)</translation>
    </message>
    <message>
        <source>empty = same as θ1</source>
        <translation>空欄 = θ1 と同じ</translation>
    </message>
    <message>
        <location filename="../../ui/field_spec.cpp" line="119"/>
        <source>Scallop height</source>
        <translation>カスプ高さ</translation>
    </message>
    <message>
        <source>Shape</source>
        <translation>形状</translation>
    </message>
    <message>
        <source>Touched from</source>
        <translation>接触する側</translation>
    </message>
    <message>
        <source>P1 machine X</source>
        <translation>P1 機械座標 X</translation>
    </message>
    <message>
        <source>P1 machine Y</source>
        <translation>P1 機械座標 Y</translation>
    </message>
    <message>
        <source>Top face machine Z</source>
        <translation>上面 機械座標 Z</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>許容差</translation>
    </message>
    <message>
        <source>Nominal diameter / width X</source>
        <translation>呼び径 / 幅 X</translation>
    </message>
    <message>
        <source>Nominal length Y</source>
        <translation>呼び長さ Y</translation>
    </message>
    <message>
        <source>Touch depth</source>
        <translation>接触深さ</translation>
    </message>
    <message>
        <source>Clearance</source>
        <translation>逃げ量</translation>
    </message>
    <message>
        <source>Search distance</source>
        <translation>探索距離</translation>
    </message>
    <message>
        <source>Probing feed (mm/min)</source>
        <translation>測定送り (mm/min)</translation>
    </message>
    <message>
        <source>not touched</source>
        <translation>未測定</translation>
    </message>
    <message>
        <source>Step-over (× D)</source>
        <translation>ステップオーバ(× D)</translation>
    </message>
    <message>
        <source>technology data's</source>
        <translation>技術データの値</translation>
    </message>
</context>
<context>
    <name>taiwa::ui::TechnologyDialog</name>
    <message>
        <location filename="../../ui/technology_dialog.cpp" line="29"/>
        <source>pilot hole stops this far above the floor</source>
        <translation>下穴は底からこの高さで止める</translation>
    </message>
    <message>
        <location filename="../../ui/technology_dialog.cpp" line="31"/>
        <source>wall allowance left by roughing</source>
        <translation>荒加工の壁仕上げ代</translation>
    </message>
    <message>
        <location filename="../../ui/technology_dialog.cpp" line="33"/>
        <source>wall allowance of the semi-finish pass (F = 3)</source>
        <translation>中仕上げの壁仕上げ代 (F = 3)</translation>
    </message>
    <message>
        <location filename="../../ui/technology_dialog.cpp" line="35"/>
        <source>floor allowance left by roughing</source>
        <translation>荒加工の底仕上げ代</translation>
    </message>
    <message>
        <location filename="../../ui/technology_dialog.cpp" line="37"/>
        <source>roughing layer depth / tool diameter</source>
        <translation>荒加工の1層の深さ / 工具径</translation>
    </message>
</context>
</TS>
