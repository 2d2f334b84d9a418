<?xml version="1.0" encoding="utf-8"?>
<!-- Texts of the station window (lupdate from ui/ and core/, the module descriptions and the labels of the module drawings, by resources/i18n/update-ts.py, translated by hand); compiled to .qm by lrelease at build time. -->
<!DOCTYPE TS>
<TS version="2.1" language="ja_JP">
    <context>
        <name>taiwa::ui::DxfImportDialog</name>
        <message>
            <source>Import DXF</source>
            <translation>DXF のインポート</translation>
        </message>
        <message>
            <source>No drawing chosen</source>
            <translation>図面が選ばれていません</translation>
        </message>
        <message>
            <source>Choose…</source>
            <translation>選択…</translation>
        </message>
        <message>
            <source>The layers whose lines, arcs, circles, polylines and splines are imported</source>
            <translation>線・円弧・円・ポリライン・スプラインを取り込むレイヤ</translation>
        </message>
        <message>
            <source>Layers</source>
            <translation>レイヤ</translation>
        </message>
        <message>
            <source>Ends at most this far apart are joined into one contour; wider gaps are reported</source>
            <translation>この距離以内の端点はつないで一つの輪郭にします。これより広い隙間は報告します</translation>
        </message>
        <message>
            <source>Gap tolerance</source>
            <translation>隙間の許容値</translation>
        </message>
        <message>
            <source>What the drawing gives</source>
            <translation>図面から得られたもの</translation>
        </message>
        <message>
            <source>Figure elements to add</source>
            <translation>追加する図形要素</translation>
        </message>
        <message>
            <source>Import</source>
            <translation>インポート</translation>
        </message>
        <message>
            <source>DXF drawings (*.dxf *.DXF)</source>
            <translation>DXF 図面 (*.dxf *.DXF)</translation>
        </message>
        <message>
            <source>%1 entities</source>
            <translation>%1 個の要素</translation>
        </message>
        <message>
            <source>Refused: %1</source>
            <translation>読み込めません: %1</translation>
        </message>
        <message>
            <source>No layer is ticked.</source>
            <translation>レイヤが選ばれていません。</translation>
        </message>
        <message>
            <source>%1 closed and %2 open contours, drawn in %3.</source>
            <translation>閉じた輪郭 %1 個、開いた輪郭 %2 個 (図面の単位 %3)。</translation>
        </message>
        <message>
            <source>%1 ends joined over gaps within the tolerance; the largest %2 mm.</source>
            <translation>許容値以内の隙間で端点を %1 か所つなぎました。最大 %2 mm。</translation>
        </message>
        <message>
            <source>Gap: %1</source>
            <translation>隙間: %1</translation>
        </message>
        <message>
            <source>Branch: %1</source>
            <translation>分岐: %1</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::ExportDialog</name>
        <message>
            <source>Export tape and sheet</source>
            <translation>テープと作業指示書の出力</translation>
        </message>
        <message>
            <source>the folder the files are written into</source>
            <translation>ファイルを書き込むフォルダ</translation>
        </message>
        <message>
            <source>Choose…</source>
            <translation>選択…</translation>
        </message>
        <message>
            <source>Folder</source>
            <translation>フォルダ</translation>
        </message>
        <message>
            <source>Controller dialect</source>
            <translation>NC 形式 (制御装置)</translation>
        </message>
        <message>
            <source>The job's own</source>
            <translation>ジョブの単位</translation>
        </message>
        <message>
            <source>Millimetres</source>
            <translation>ミリメートル</translation>
        </message>
        <message>
            <source>Inches</source>
            <translation>インチ</translation>
        </message>
        <message>
            <source>Units</source>
            <translation>単位</translation>
        </message>
        <message>
            <source>The sheet shows the setup and every step in a picture</source>
            <translation>作業指示書に段取りと各工程の図を載せる</translation>
        </message>
        <message>
            <source>Pictures</source>
            <translation>図</translation>
        </message>
        <message>
            <source>The grid the verification cuts the steps into before the files are written: finer finds smaller gouges and takes longer.</source>
            <translation>出力前の検証で工程を削り込む格子: 細かいほど小さな削り込みを見つけ、時間がかかります。</translation>
        </message>
        <message>
            <source>Verification grid</source>
            <translation>検証の格子</translation>
        </message>
        <message>
            <source>Export</source>
            <translation>出力</translation>
        </message>
        <message>
            <source>Export into folder</source>
            <translation>出力先フォルダ</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::FigurePanel</name>
        <message>
            <source>The figure's contours have no chamfer.</source>
            <translation>図形の輪郭に面取りはありません。</translation>
        </message>
        <message>
            <source>The figure's contours have no rounding.</source>
            <translation>図形の輪郭に丸みはありません。</translation>
        </message>
        <message>
            <source>Click a chamfer in the view to change it (%1 in the figure).</source>
            <translation>変更する面取りをビューでクリックしてください (図形に %1 個)。</translation>
        </message>
        <message>
            <source>Click a rounding in the view to change it (%1 in the figure).</source>
            <translation>変更する丸みをビューでクリックしてください (図形に %1 個)。</translation>
        </message>
        <message>
            <source>%1: chamfer between %2 and %3, length</source>
            <translation>%1: %2 と %3 の間の面取り、長さ</translation>
        </message>
        <message>
            <source>%1: rounding between %2 and %3, radius</source>
            <translation>%1: %2 と %3 の間の丸み、半径</translation>
        </message>
        <message>
            <source>The text has a refusal: correct it before revising a corner.</source>
            <translation>テキストにエラーがあります。角を修正する前に直してください。</translation>
        </message>
        <message>
            <source>Revise corner %1 of %2</source>
            <translation>%2 の角 %1 を修正</translation>
        </message>
        <message>
            <source>Figure elements, one statement a line</source>
            <translation>図形要素 (1 行に 1 文)</translation>
        </message>
        <message>
            <source>P1 = POINT/10, 20
L1 = LINE/P1, ATANGL, 90
K1 = CONTOUR/L1, ROUND, 5, L2, …</source>
            <translation>P1 = POINT/10, 20
L1 = LINE/P1, ATANGL, 90
K1 = CONTOUR/L1, ROUND, 5, L2, …</translation>
        </message>
        <message>
            <source>What the text refuses; click one to go to its place</source>
            <translation>テキストのエラー。クリックするとその箇所へ移動します</translation>
        </message>
        <message>
            <source>Revise chamfer</source>
            <translation>面取りを修正</translation>
        </message>
        <message>
            <source>Revise rounding</source>
            <translation>丸みを修正</translation>
        </message>
        <message>
            <source>Fit</source>
            <translation>全体表示</translation>
        </message>
        <message>
            <source>Frame the stock, the points and the contours</source>
            <translation>素材・点・輪郭の全体を表示</translation>
        </message>
        <message>
            <source>Edit figure</source>
            <translation>図形を編集</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::FigureView</name>
        <message>
            <source>Click: pick an element. Wheel: zoom. Drag: pan. Double click: fit.</source>
            <translation>クリック: 要素を選択。ホイール: ズーム。ドラッグ: 移動。ダブルクリック: 全体表示。</translation>
        </message>
        <message>
            <source>Click: the next point of the passes. Wheel: zoom. Drag: pan. Double click: fit.</source>
            <translation>クリック: パスの次の点。ホイール: ズーム。ドラッグ: 移動。ダブルクリック: 全体表示。</translation>
        </message>
        <message>
            <source>Drawing passes: click the start, then the end of each pass; wheel: zoom, drag: pan</source>
            <translation>パスの描画: 始点、続いて各パスの終点をクリック。ホイール: ズーム、ドラッグ: 移動</translation>
        </message>
        <message>
            <source>X →  Y ↑   wheel: zoom, drag: pan, double click: fit</source>
            <translation>X →  Y ↑   ホイール: ズーム、ドラッグ: 移動、ダブルクリック: 全体表示</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::FileActions</name>
        <message>
            <source>%1 (shop server)</source>
            <translation>%1（共有サーバー）</translation>
        </message>
        <message>
            <source>untitled</source>
            <translation>無題</translation>
        </message>
        <message>
            <source>Unsaved changes</source>
            <translation>未保存の変更</translation>
        </message>
        <message>
            <source>The job has unsaved changes. Save them?</source>
            <translation>ジョブに未保存の変更があります。保存しますか?</translation>
        </message>
        <message>
            <source>New job</source>
            <translation>新規ジョブ</translation>
        </message>
        <message>
            <source>Open job</source>
            <translation>ジョブを開く</translation>
        </message>
        <message>
            <source>Import a turned part (STEP)</source>
            <translation>旋削部品をインポート (STEP)</translation>
        </message>
        <message>
            <source>STEP models (*.step *.stp *.STEP *.STP)</source>
            <translation>STEP モデル (*.step *.stp *.STEP *.STP)</translation>
        </message>
        <message>
            <source>Cannot import</source>
            <translation>インポートできません</translation>
        </message>
        <message numerus="yes">
            <source>Imported %1: %n turned profile(s)</source>
            <translation>
                <numerusform>%1 をインポートしました: 旋削形状 %n 個</numerusform>
            </translation>
        </message>
        <message>
            <source>Import a surface (STEP face set)</source>
            <translation>曲面の取り込み (STEP の面の集合)</translation>
        </message>
        <message>
            <source>Imported %1 as a surface: moved %2 mm in Z to put its top at Z 0; the paths stay within %3 µm of its faces</source>
            <translation>%1 を曲面として取り込みました: 最上点を Z 0 にするため Z に %2 mm 移動、パスと面との差は %3 µm 以内です</translation>
        </message>
        <message>
            <source>Cannot open job</source>
            <translation>ジョブを開けません</translation>
        </message>
        <message>
            <source>Opened %1</source>
            <translation>%1 を開きました</translation>
        </message>
        <message>
            <source>Save job</source>
            <translation>ジョブを保存</translation>
        </message>
        <message>
            <source>%1 was changed on disk since this window opened or saved it (by another window or program).</source>
            <translation>%1 は、このウィンドウで開いた後または保存した後に(別のウィンドウやプログラムによって)ディスク上で変更されています。</translation>
        </message>
        <message>
            <source> Not saved: use Save As.</source>
            <translation> 保存していません: 「名前を付けて保存」を使ってください。</translation>
        </message>
        <message>
            <source> Overwrite it with this window's job?</source>
            <translation> このウィンドウのジョブで上書きしますか?</translation>
        </message>
        <message>
            <source>Cannot save job</source>
            <translation>ジョブを保存できません</translation>
        </message>
        <message>
            <source>Saved %1</source>
            <translation>%1 を保存しました</translation>
        </message>
        <message>
            <source>Export</source>
            <translation>出力</translation>
        </message>
        <message>
            <source>The job has input errors; fix them before exporting.</source>
            <translation>ジョブに入力エラーがあります。出力する前に修正してください。</translation>
        </message>
        <message>
            <source>Export failed</source>
            <translation>出力に失敗しました</translation>
        </message>
        <message numerus="yes">
            <source>The verification found %n faults (the first: %1).</source>
            <translation>
                <numerusform>検証で %n 件の不具合が見つかりました (最初: %1)。</numerusform>
            </translation>
        </message>
        <message>
            <source>Write the files anyway, with the faults on the sheet?</source>
            <translation>不具合を作業指示書に記して、それでも出力しますか?</translation>
        </message>
        <message>
            <source>Exported %1 files into %2</source>
            <translation>%1 個のファイルを %2 に出力しました</translation>
        </message>
        <message>
            <source>(pictures missing: %1)</source>
            <translation>(図がありません: %1)</translation>
        </message>
        <message>
            <source>an untitled job</source>
            <translation>無題のジョブ</translation>
        </message>
        <message>
            <source>Recover job</source>
            <translation>ジョブの復元</translation>
        </message>
        <message>
            <source>Taiwa was not closed properly while editing %1. Its autosaved copy is newer than the file. Restore the autosaved copy?</source>
            <translation>%1 の編集中に Taiwa が正しく終了しませんでした。自動保存のコピーがファイルより新しいです。自動保存のコピーを復元しますか?</translation>
        </message>
        <message>
            <source>Restored the autosaved job (not saved to a file yet)</source>
            <translation>自動保存のジョブを復元しました(まだファイルには保存されていません)</translation>
        </message>
        <message>
            <source>(none)</source>
            <translation>(なし)</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::JobProperties</name>
        <message>
            <source>Name</source>
            <translation>名前</translation>
        </message>
        <message>
            <source>Material</source>
            <translation>材質</translation>
        </message>
        <message>
            <source>Units</source>
            <translation>単位</translation>
        </message>
        <message>
            <source>Machine</source>
            <translation>機械</translation>
        </message>
        <message>
            <source>Clamping</source>
            <translation>保持</translation>
        </message>
        <message>
            <source>Jaws' height</source>
            <translation>ジョーの高さ</translation>
        </message>
        <message>
            <source>mm</source>
            <translation>mm</translation>
        </message>
        <message>
            <source>inch (converts every length)</source>
            <translation>インチ(全ての長さを換算)</translation>
        </message>
        <message>
            <source>not given</source>
            <translation>指定なし</translation>
        </message>
        <message>
            <source>vice on the X faces</source>
            <translation>バイスで X 面をつかむ</translation>
        </message>
        <message>
            <source>vice on the Y faces</source>
            <translation>バイスで Y 面をつかむ</translation>
        </message>
        <message>
            <source>How the block is held, for the instruction sheet's setup picture</source>
            <translation>素材の保持方法（作業指示書の段取り図用）</translation>
        </message>
        <message>
            <source>How far up the block's sides the jaws grip, from its bottom</source>
            <translation>ジョーが素材の側面をつかむ高さ（底面から）</translation>
        </message>
        <message>
            <source>Machine %1</source>
            <translation>機械 %1</translation>
        </message>
        <message>
            <source>Change clamping</source>
            <translation>保持の変更</translation>
        </message>
        <message>
            <source>Edit job name</source>
            <translation>ジョブ名の編集</translation>
        </message>
        <message>
            <source>Change material</source>
            <translation>材質の変更</translation>
        </message>
        <message>
            <source>Change length unit</source>
            <translation>単位の変更</translation>
        </message>
        <message>
            <source>not a number</source>
            <translation>数値ではありません</translation>
        </message>
        <message>
            <source>Edit %1</source>
            <translation>%1 の編集</translation>
        </message>
        <message>
            <source> (unknown)</source>
            <translation>(不明)</translation>
        </message>
        <message>
            <source>Stock width (X)</source>
            <translation>素材の幅 (X)</translation>
        </message>
        <message>
            <source>Stock length (Y)</source>
            <translation>素材の長さ (Y)</translation>
        </message>
        <message>
            <source>Stock height (Z)</source>
            <translation>素材の高さ (Z)</translation>
        </message>
        <message>
            <source>Bar diameter</source>
            <translation>棒材の直径</translation>
        </message>
        <message>
            <source>Bar length</source>
            <translation>棒材の長さ</translation>
        </message>
        <message>
            <source>Face stock</source>
            <translation>端面の取り代</translation>
        </message>
        <message>
            <source>Bore (0: solid)</source>
            <translation>中ぐり穴径 (0: 中実)</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::NcView</name>
        <message>
            <source>&amp;NC dialect:</source>
            <translation>NC 形式(&amp;N):</translation>
        </message>
        <message numerus="yes">
            <source>%n block(s)</source>
            <translation>
                <numerusform>%n ブロック</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::PassesBar</name>
        <message>
            <source>Remove the last point of the passes</source>
            <translation>パスの最後の点を削除</translation>
        </message>
        <message>
            <source>Clear the passes</source>
            <translation>パスをクリア</translation>
        </message>
        <message>
            <source>Draw passes</source>
            <translation>パスを描く</translation>
        </message>
        <message>
            <source>Click in the view: the first point is where the tool starts, each next one ends a pass</source>
            <translation>ビューをクリック: 最初の点が工具の開始位置、以降の点がそれぞれパスの終点</translation>
        </message>
        <message>
            <source>Remove last point</source>
            <translation>最後の点を削除</translation>
        </message>
        <message>
            <source>Take back the last point drawn</source>
            <translation>最後に描いた点を取り消す</translation>
        </message>
        <message>
            <source>Clear</source>
            <translation>クリア</translation>
        </message>
        <message>
            <source>Remove every pass of this unit</source>
            <translation>このユニットのパスをすべて削除</translation>
        </message>
        <message>
            <source>Draw the start point of the passes</source>
            <translation>パスの始点を描く</translation>
        </message>
        <message>
            <source>Draw a pass</source>
            <translation>パスを描く</translation>
        </message>
        <message>
            <source>No pass drawn: press Draw passes and click where the tool starts.</source>
            <translation>パスがありません: 「パスを描く」を押し、工具の開始位置をクリックしてください。</translation>
        </message>
        <message>
            <source>The start point is drawn: click where the first pass ends.</source>
            <translation>始点を描きました: 最初のパスの終点をクリックしてください。</translation>
        </message>
        <message>
            <source>1 pass drawn.</source>
            <translation>パス 1 本。</translation>
        </message>
        <message>
            <source>%1 passes drawn.</source>
            <translation>パス %1 本。</translation>
        </message>
        <message>
            <source>The area %1 is not a closed contour of the figure.</source>
            <translation>領域 %1 は図形の閉じた輪郭ではありません。</translation>
        </message>
        <message>
            <source>The start point is too near the walls.</source>
            <translation>始点が壁に近すぎます。</translation>
        </message>
        <message>
            <source>Pass %1 leaves the area.</source>
            <translation>パス %1 が領域からはみ出します。</translation>
        </message>
        <message>
            <source>The strips sweep the whole area.</source>
            <translation>帯が領域全体を削ります。</translation>
        </message>
        <message>
            <source>Unswept: %1 in one place.</source>
            <translation>未切削: 1 か所で %1。</translation>
        </message>
        <message>
            <source>Unswept: %1 in %2 places.</source>
            <translation>未切削: %2 か所で %1。</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::PlanRunner</name>
        <message>
            <source>%1 changed by %2 at station %3; the plan is run again</source>
            <translation>%1 が %2 によりステーション %3 で変更されました。計画を再実行します</translation>
        </message>
        <message>
            <source>(no program: the job has input errors)</source>
            <translation>(プログラムなし: ジョブに入力エラーがあります)</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::ProfileEditor</name>
        <message>
            <source>Edge</source>
            <translation>稜線</translation>
        </message>
        <message>
            <source>Element</source>
            <translation>要素</translation>
        </message>
        <message>
            <source>X (dia.)</source>
            <translation>X (直径)</translation>
        </message>
        <message>
            <source>Z</source>
            <translation>Z</translation>
        </message>
        <message>
            <source>R</source>
            <translation>R</translation>
        </message>
        <message>
            <source>Centre X</source>
            <translation>中心 X</translation>
        </message>
        <message>
            <source>Centre Z</source>
            <translation>中心 Z</translation>
        </message>
        <message>
            <source>Corner</source>
            <translation>コーナ</translation>
        </message>
        <message>
            <source>Size</source>
            <translation>寸法</translation>
        </message>
        <message>
            <source>Ra µm</source>
            <translation>Ra µm</translation>
        </message>
        <message>
            <source>Tolerance</source>
            <translation>許容差</translation>
        </message>
        <message>
            <source>Thread pitch</source>
            <translation>ねじピッチ</translation>
        </message>
        <message>
            <source>Allowance</source>
            <translation>研削代</translation>
        </message>
        <message>
            <source>Adjustment</source>
            <translation>調整量</translation>
        </message>
        <message>
            <source>Relief groove</source>
            <translation>逃げ溝</translation>
        </message>
        <message>
            <source>Width</source>
            <translation>幅</translation>
        </message>
        <message>
            <source>Depth</source>
            <translation>深さ</translation>
        </message>
        <message>
            <source>line</source>
            <translation>直線</translation>
        </message>
        <message>
            <source>arc CW (G2)</source>
            <translation>円弧 CW (G2)</translation>
        </message>
        <message>
            <source>arc CCW (G3)</source>
            <translation>円弧 CCW (G3)</translation>
        </message>
        <message>
            <source>none</source>
            <translation>なし</translation>
        </message>
        <message>
            <source>chamfer</source>
            <translation>面取り</translation>
        </message>
        <message>
            <source>rounding</source>
            <translation>丸み</translation>
        </message>
        <message>
            <source>Allowances and grooves drawn ×%1</source>
            <translation>研削代と逃げ溝を ×%1 で表示</translation>
        </message>
        <message>
            <source>Profile, in cutting order (X is a diameter; arcs: R, or the centre)</source>
            <translation>形状(切削順、X は直径。円弧は R または中心で指定)</translation>
        </message>
        <message>
            <source>Grinding allowance per edge (empty: adjustment from the finishing tool's nose radius, depth = allowance, no width = no groove)</source>
            <translation>稜線ごとの研削代(空欄: 調整量は仕上げ工具のノーズ半径、深さ = 研削代、幅なし = 溝なし)</translation>
        </message>
        <message>
            <source>Add row</source>
            <translation>行を追加</translation>
        </message>
        <message>
            <source>Insert row</source>
            <translation>行を挿入</translation>
        </message>
        <message>
            <source>Delete row</source>
            <translation>行を削除</translation>
        </message>
        <message>
            <source>Revise chamfers</source>
            <translation>面取りを修正</translation>
        </message>
        <message>
            <source>Revise roundings</source>
            <translation>丸みを修正</translation>
        </message>
        <message>
            <source>Done</source>
            <translation>完了</translation>
        </message>
        <message>
            <source>Add allowance for picked edge</source>
            <translation>選択した稜線に研削代を追加</translation>
        </message>
        <message>
            <source>Delete allowance</source>
            <translation>研削代を削除</translation>
        </message>
        <message>
            <source>Element of row %1</source>
            <translation>行 %1 の要素</translation>
        </message>
        <message>
            <source>Corner of row %1</source>
            <translation>行 %1 のコーナ</translation>
        </message>
        <message>
            <source>Groove kind of allowance %1</source>
            <translation>研削代 %1 の溝の種類</translation>
        </message>
        <message>
            <source>profile row %1, %2</source>
            <translation>形状 %1 行目、%2</translation>
        </message>
        <message>
            <source>allowance row %1, %2</source>
            <translation>研削代 %1 行目、%2</translation>
        </message>
        <message>
            <source>not a number</source>
            <translation>数値ではありません</translation>
        </message>
        <message>
            <source>row %1: not a number</source>
            <translation>行 %1: 数値ではありません</translation>
        </message>
        <message>
            <source>%1 of row %2</source>
            <translation>行 %2 の %1</translation>
        </message>
        <message>
            <source>allowance %1: not a number</source>
            <translation>研削代 %1: 数値ではありません</translation>
        </message>
        <message>
            <source>%1 of allowance %2</source>
            <translation>研削代 %2 の %1</translation>
        </message>
        <message>
            <source>Add row %1</source>
            <translation>行 %1 を追加</translation>
        </message>
        <message>
            <source>Delete row %1</source>
            <translation>行 %1 を削除</translation>
        </message>
        <message>
            <source>Pick an edge in the view first.</source>
            <translation>先に図で稜線を選んでください。</translation>
        </message>
        <message>
            <source>%1 has an allowance already.</source>
            <translation>%1 にはすでに研削代があります。</translation>
        </message>
        <message>
            <source>Add grinding allowance for %1</source>
            <translation>%1 に研削代を追加</translation>
        </message>
        <message>
            <source>Delete allowance %1</source>
            <translation>研削代 %1 を削除</translation>
        </message>
        <message>
            <source>Chamfer %1: leg</source>
            <translation>面取り %1: 辺の長さ</translation>
        </message>
        <message>
            <source>Rounding %1: radius</source>
            <translation>丸み %1: 半径</translation>
        </message>
        <message>
            <source>chamfers</source>
            <translation>面取り</translation>
        </message>
        <message>
            <source>roundings</source>
            <translation>丸み</translation>
        </message>
        <message>
            <source>The profile has no %1.</source>
            <translation>形状に%1はありません。</translation>
        </message>
        <message>
            <source>%1 %2: pick one in the view</source>
            <translation>%2 %1 個: 図で一つ選んでください</translation>
        </message>
        <message>
            <source>Revise %1</source>
            <translation>%1 を修正</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::ProfileView</name>
        <message>
            <source>Z →   X (diameter) ↑</source>
            <translation>Z →   X (直径) ↑</translation>
        </message>
        <message>
            <source>- - - to cut (grinding allowance)</source>
            <translation>- - - 切削形状(研削代付き)</translation>
        </message>
        <message>
            <source>- - - to cut (grinding allowance, its depth drawn ×%1)</source>
            <translation>- - - 切削形状(研削代付き、深さを ×%1 で表示)</translation>
        </message>
    </context>
    <context>
        <name>QObject</name>
        <message>
            <source>(no program: the job has input errors)</source>
            <translation>(プログラムなし: ジョブに入力エラーがあります)</translation>
        </message>
        <message>
            <source>(no program: %1)</source>
            <translation>(プログラムなし: %1)</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::SectionBar</name>
        <message>
            <source>No section</source>
            <translation>断面なし</translation>
        </message>
        <message>
            <source>Section across X</source>
            <translation>X 方向の断面</translation>
        </message>
        <message>
            <source>Section across Y</source>
            <translation>Y 方向の断面</translation>
        </message>
        <message>
            <source>Section across Z</source>
            <translation>Z 方向の断面</translation>
        </message>
        <message>
            <source>Cut the stock open along a plane to see inside it</source>
            <translation>素材を平面で切って内部を見る</translation>
        </message>
        <message>
            <source>Where the plane cuts the stock</source>
            <translation>平面が素材を切る位置</translation>
        </message>
        <message>
            <source>A plane across X or Y turned about Z</source>
            <translation>X または Y 方向の平面を Z 軸まわりに回す角度</translation>
        </message>
        <message>
            <source>Flip</source>
            <translation>反転</translation>
        </message>
        <message>
            <source>Take away the material on the other side of the plane</source>
            <translation>平面の反対側の材料を取り除く</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::StationWindow</name>
        <message>
            <source>Modules</source>
            <translation>モジュール</translation>
        </message>
        <message>
            <source>Machining units, in order</source>
            <translation>加工ユニット(加工順)</translation>
        </message>
        <message>
            <source>Job</source>
            <translation>ジョブ</translation>
        </message>
        <message>
            <source>Unit</source>
            <translation>ユニット</translation>
        </message>
        <message>
            <source>Technology data…</source>
            <translation>加工技術データ…</translation>
        </message>
        <message>
            <source>Tool library…</source>
            <translation>工具ライブラリ…</translation>
        </message>
        <message>
            <source>Pick a module on the left to add a machining unit.</source>
            <translation>左のモジュールを選んで加工ユニットを追加してください。</translation>
        </message>
        <message>
            <source>No 3-D preview: this display has no OpenGL.</source>
            <translation>3D プレビューなし: このディスプレイは OpenGL を使えません。</translation>
        </message>
        <message>
            <source>3-D view</source>
            <translation>3D ビュー</translation>
        </message>
        <message>
            <source>Figure</source>
            <translation>図形</translation>
        </message>
        <message>
            <source>Steps</source>
            <translation>工程</translation>
        </message>
        <message>
            <source>Steps by path</source>
            <translation>系統別工程</translation>
        </message>
        <message>
            <source>Path 1</source>
            <translation>系統 1</translation>
        </message>
        <message>
            <source>Path 2</source>
            <translation>系統 2</translation>
        </message>
        <message>
            <source>&amp;File</source>
            <translation>ファイル(&amp;F)</translation>
        </message>
        <message>
            <source>&amp;New</source>
            <translation>新規(&amp;N)</translation>
        </message>
        <message>
            <source>&amp;Open…</source>
            <translation>開く(&amp;O)…</translation>
        </message>
        <message>
            <source>Open &amp;recent</source>
            <translation>最近使ったファイル(&amp;R)</translation>
        </message>
        <message>
            <source>&amp;Import turned part (STEP)…</source>
            <translation>旋削部品をインポート (STEP)(&amp;I)…</translation>
        </message>
        <message>
            <source>Import s&amp;urface (STEP face set)…</source>
            <translation>曲面の取り込み (STEP の面の集合)(&amp;U)…</translation>
        </message>
        <message>
            <source>Import &amp;DXF contours…</source>
            <translation>DXF 輪郭をインポート(&amp;D)…</translation>
        </message>
        <message>
            <source>&amp;Save</source>
            <translation>保存(&amp;S)</translation>
        </message>
        <message>
            <source>Save &amp;as…</source>
            <translation>名前を付けて保存(&amp;A)…</translation>
        </message>
        <message>
            <source>Open from the s&amp;hop server…</source>
            <translation>共有サーバーから開く(&amp;H)…</translation>
        </message>
        <message>
            <source>Save to the shop ser&amp;ver</source>
            <translation>共有サーバーに保存(&amp;V)</translation>
        </message>
        <message>
            <source>&amp;Export tape and sheet…</source>
            <translation>テープと作業指示書を出力(&amp;E)…</translation>
        </message>
        <message>
            <source>Ctrl+E</source>
            <translation>Ctrl+E</translation>
        </message>
        <message>
            <source>&amp;Quit</source>
            <translation>終了(&amp;Q)</translation>
        </message>
        <message>
            <source>&amp;Edit</source>
            <translation>編集(&amp;E)</translation>
        </message>
        <message>
            <source>&amp;Undo</source>
            <translation>元に戻す(&amp;U)</translation>
        </message>
        <message>
            <source>&amp;Redo</source>
            <translation>やり直し(&amp;R)</translation>
        </message>
        <message>
            <source>Ctrl+Shift+Z</source>
            <translation>Ctrl+Shift+Z</translation>
        </message>
        <message>
            <source>Ctrl+Y</source>
            <translation>Ctrl+Y</translation>
        </message>
        <message>
            <source>&amp;Job</source>
            <translation>ジョブ(&amp;J)</translation>
        </message>
        <message>
            <source>&amp;Technology data…</source>
            <translation>加工技術データ(&amp;T)…</translation>
        </message>
        <message>
            <source>Ctrl+T</source>
            <translation>Ctrl+T</translation>
        </message>
        <message>
            <source>Tool &amp;library…</source>
            <translation>工具ライブラリ(&amp;L)…</translation>
        </message>
        <message>
            <source>Ctrl+L</source>
            <translation>Ctrl+L</translation>
        </message>
        <message>
            <source>&amp;View</source>
            <translation>表示(&amp;V)</translation>
        </message>
        <message>
            <source>Tool &amp;paths</source>
            <translation>工具経路(&amp;P)</translation>
        </message>
        <message>
            <source>&amp;Stock as cut</source>
            <translation>加工された素材(&amp;S)</translation>
        </message>
        <message>
            <source>Pa&amp;rt</source>
            <translation>製品形状(&amp;R)</translation>
        </message>
        <message>
            <source>The finished pockets' outlines, or the turned part</source>
            <translation>仕上がったポケットの輪郭、または旋削形状</translation>
        </message>
        <message>
            <source>&amp;Zoom to the selected step</source>
            <translation>選択した工程に合わせて拡大(&amp;Z)</translation>
        </message>
        <message>
            <source>&amp;Language</source>
            <translation>言語(&amp;L)</translation>
        </message>
        <message>
            <source>No translation for %1: English is shown.</source>
            <translation>%1 の翻訳がありません。英語で表示します。</translation>
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
        <message>
            <source>Tool library: %1 (using the built-in library)</source>
            <translation>工具ライブラリ: %1(内蔵ライブラリを使用)</translation>
        </message>
        <message>
            <source>DXF contours become figure elements, which a lathe job does not use.</source>
            <translation>DXF の輪郭は図形要素になりますが、旋削ジョブでは使いません。</translation>
        </message>
        <message>
            <source>Import DXF contours</source>
            <translation>DXF 輪郭のインポート</translation>
        </message>
        <message>
            <source>Edit %1 of unit %2</source>
            <translation>ユニット %2 の %1 を編集</translation>
        </message>
        <message>
            <source>Not up to date: the job has input errors. The 3-D view and the NC program show the last valid job. First error: %1</source>
            <translation>最新ではありません: ジョブに入力エラーがあります。3D 表示と NC プログラムは最後に有効だったジョブを表示しています。最初のエラー: %1</translation>
        </message>
        <message>
            <source>job</source>
            <translation>ジョブ</translation>
        </message>
        <message numerus="yes">
            <source>%n problem(s) in other units</source>
            <translation>
                <numerusform>他のユニットに %n 件の問題</numerusform>
            </translation>
        </message>
        <message>
            <source>Edit technology data</source>
            <translation>加工技術データの編集</translation>
        </message>
        <message numerus="yes">
            <source>%1 is also open in %n other window(s): a save here asks before it overwrites what another window saved.</source>
            <translation>
                <numerusform>%1 は他の %n 個のウィンドウでも開かれています: ここで保存するときは、他のウィンドウが保存した内容を上書きする前に確認します。</numerusform>
            </translation>
        </message>
        <message>
            <source>%1 of unit %2</source>
            <translation>ユニット %2 の %1</translation>
        </message>
        <message>
            <source>Rename unit %1</source>
            <translation>ユニット %1 の名前を変更</translation>
        </message>
        <message>
            <source>Dialect %1</source>
            <translation>NC 形式 %1</translation>
        </message>
        <message>
            <source>Spindle speed of %1, unit %2</source>
            <translation>%1の主軸回転数 (ユニット %2)</translation>
        </message>
        <message>
            <source>Feed of %1, unit %2</source>
            <translation>%1の送り (ユニット %2)</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::StepPanel</name>
        <message>
            <source>■ Stop (&amp;Y)</source>
            <translation>■ 停止(&amp;Y)</translation>
        </message>
        <message>
            <source>▶ Pla&amp;y</source>
            <translation>▶ 再生(&amp;Y)</translation>
        </message>
        <message>
            <source>&amp;Stock</source>
            <translation>素材(&amp;S)</translation>
        </message>
        <message>
            <source>The stock as the simulation cuts it, instead of a glass block</source>
            <translation>ガラスのブロックではなく、シミュレーションで削った素材を表示</translation>
        </message>
        <message>
            <source>&amp;Before step</source>
            <translation>加工前(&amp;B)</translation>
        </message>
        <message>
            <source>The stock as it is before the selected step, instead of after it</source>
            <translation>選んだ工程の後ではなく、その前の素材を表示</translation>
        </message>
        <message>
            <source>&amp;All steps</source>
            <translation>全工程(&amp;A)</translation>
        </message>
        <message>
            <source>&amp;Iso</source>
            <translation>等角(&amp;I)</translation>
        </message>
        <message>
            <source>&amp;Top</source>
            <translation>上面(&amp;T)</translation>
        </message>
        <message>
            <source>F&amp;ront</source>
            <translation>正面(&amp;R)</translation>
        </message>
        <message>
            <source>&amp;Zoom to step</source>
            <translation>工程に合わせる(&amp;Z)</translation>
        </message>
        <message>
            <source>Zoom to the selected step, the view turned as it is (all steps: the whole job)</source>
            <translation>選択した工程に合わせて拡大します。視点の向きはそのままです(全工程: ジョブ全体)</translation>
        </message>
        <message>
            <source>Pat&amp;hs</source>
            <translation>工具経路(&amp;H)</translation>
        </message>
        <message>
            <source>The tool paths drawn; off, the stock and the colour map show unhidden</source>
            <translation>工具経路を表示します。オフにすると素材とカラーマップが経路に隠れません</translation>
        </message>
        <message>
            <source>One block back in the selected step</source>
            <translation>選択した工程で1ブロック戻る</translation>
        </message>
        <message>
            <source>One block on in the selected step, the material coming off</source>
            <translation>選択した工程で1ブロック進む(素材が削られる様子を表示)</translation>
        </message>
        <message>
            <source>How many blocks Play moves on ten times a second with a step selected</source>
            <translation>工程を選択して再生するとき、1秒に10回進めるブロック数</translation>
        </message>
        <message>
            <source>No steps: the job has input errors.</source>
            <translation>工程なし: ジョブに入力エラーがあります。</translation>
        </message>
        <message numerus="yes">
            <source>%n step(s), %1 min, %2 tool change(s) (updating…)</source>
            <translation>
                <numerusform>%n 工程、%1 分、工具交換 %2 回(更新中…)</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n step(s), %1 min, %2 tool change(s)</source>
            <translation>
                <numerusform>%n 工程、%1 分、工具交換 %2 回</numerusform>
            </translation>
        </message>
        <message>
            <source>&lt;b&gt;%1&lt;/b&gt; of unit %2 (%3), machining type %4</source>
            <translation>ユニット %2 (%3) の &lt;b&gt;%1&lt;/b&gt;、加工種別コード %4</translation>
        </message>
        <message>
            <source>Air to %1, cuts to %2; leaves wall %3, floor %4</source>
            <translation>%1 まで空送り、%2 まで切削; 残し代 壁 %3、底 %4</translation>
        </message>
        <message>
            <source>Outline %1, r %2</source>
            <translation>輪郭 %1、r %2</translation>
        </message>
        <message>
            <source>Inclined face at %1° from the vertical, scallop %2</source>
            <translation>傾斜面 垂直から %1°、カスプ高さ %2</translation>
        </message>
        <message>
            <source>At (%1, %2), Ø %3</source>
            <translation>位置 (%1, %2)、Ø %3</translation>
        </message>
        <message>
            <source>Wall taper %1° per side</source>
            <translation>壁テーパ 片側 %1°</translation>
        </message>
        <message>
            <source>T%1 %2: %3</source>
            <translation>T%1 %2: %3</translation>
        </message>
        <message>
            <source>Estimated %1 min (%2 min as the machine moves)</source>
            <translation>見積り %1 分(機械の動きで %2 分)</translation>
        </message>
        <message>
            <source>Estimated %1 min</source>
            <translation>予想 %1 分</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::StepTable</name>
        <message>
            <source>No.</source>
            <translation>No.</translation>
        </message>
        <message>
            <source>Unit</source>
            <translation>ユニット</translation>
        </message>
        <message>
            <source>Step</source>
            <translation>工程</translation>
        </message>
        <message>
            <source>Tool</source>
            <translation>工具</translation>
        </message>
        <message>
            <source>S</source>
            <translation>S</translation>
        </message>
        <message>
            <source>F</source>
            <translation>F</translation>
        </message>
        <message>
            <source>Start</source>
            <translation>開始深さ</translation>
        </message>
        <message>
            <source>Depth</source>
            <translation>深さ</translation>
        </message>
        <message>
            <source>Time</source>
            <translation>時間</translation>
        </message>
        <message>
            <source>Spindle speed (rpm; m/min under constant surface speed): type to set it for this unit's steps of this kind, empty it for the tool's</source>
            <translation>主軸回転数 (min⁻¹、周速一定制御では m/min)：入力するとこのユニットのこの種類の工程に設定、空にすると工具の切削条件に戻ります</translation>
        </message>
        <message>
            <source>Feed (per minute; per revolution on a lathe): type to set it for this unit's steps of this kind, empty it for the tool's</source>
            <translation>送り (毎分、旋盤では毎回転)：入力するとこのユニットのこの種類の工程に設定、空にすると工具の切削条件に戻ります</translation>
        </message>
        <message>
            <source>Set for this step kind of the unit; empty the cell for the tool's cutting data</source>
            <translation>このユニットのこの工程に設定された値です。空にすると工具の切削条件に戻ります</translation>
        </message>
        <message>
            <source>Depth of cut on the radius: of a pass; of a thread, the whole thread</source>
            <translation>半径での切込み: 1 パス分。ねじではねじ全体の深さ</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::StoreActions</name>
        <message>
            <source>Shop server</source>
            <translation>共有サーバー</translation>
        </message>
        <message>
            <source>The job store needs the shop server: TAIWA_TOOL_DB names the file %1, not a server</source>
            <translation>ジョブストアには共有サーバーが必要です: TAIWA_TOOL_DB はサーバーではなくファイル %1 を指しています</translation>
        </message>
        <message>
            <source>Open from the shop server</source>
            <translation>共有サーバーから開く</translation>
        </message>
        <message>
            <source>The shop server holds no jobs yet</source>
            <translation>共有サーバーにはまだジョブがありません</translation>
        </message>
        <message>
            <source>Job:</source>
            <translation>ジョブ:</translation>
        </message>
        <message>
            <source>Cannot open job</source>
            <translation>ジョブを開けません</translation>
        </message>
        <message>
            <source>Opened %1 from the shop server (version %2); this station holds its lock</source>
            <translation>共有サーバーから %1 を開きました（バージョン %2）。このステーションがロックを保持しています</translation>
        </message>
        <message>
            <source>Save to the shop server</source>
            <translation>共有サーバーに保存</translation>
        </message>
        <message>
            <source>Name in the job store:</source>
            <translation>ジョブストアでの名前:</translation>
        </message>
        <message>
            <source>Cannot save job</source>
            <translation>ジョブを保存できません</translation>
        </message>
        <message>
            <source>Saved %1 to the shop server as version %2</source>
            <translation>%1 を共有サーバーにバージョン %2 として保存しました</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::TechnologyDialog</name>
        <message>
            <source>Technology data</source>
            <translation>加工技術データ</translation>
        </message>
        <message>
            <source>&lt;b&gt;Value&lt;/b&gt;</source>
            <translation>&lt;b&gt;項目&lt;/b&gt;</translation>
        </message>
        <message>
            <source>&lt;b&gt;Table (%1)&lt;/b&gt;</source>
            <translation>&lt;b&gt;テーブル (%1)&lt;/b&gt;</translation>
        </message>
        <message>
            <source>&lt;b&gt;This job&lt;/b&gt; (empty = table)</source>
            <translation>&lt;b&gt;このジョブ&lt;/b&gt;(空欄 = テーブル)</translation>
        </message>
        <message>
            <source>&lt;b&gt;In force&lt;/b&gt;</source>
            <translation>&lt;b&gt;適用値&lt;/b&gt;</translation>
        </message>
        <message>
            <source>(unknown material)</source>
            <translation>(不明な材質)</translation>
        </message>
        <message>
            <source>not a number</source>
            <translation>数値ではありません</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::ToolLibraryDialog</name>
        <message>
            <source>&amp;Reset wear</source>
            <translation>摩耗をリセット(&amp;R)</translation>
        </message>
        <message>
            <source>Tool library</source>
            <translation>工具ライブラリ</translation>
        </message>
        <message>
            <source>T</source>
            <translation>T</translation>
        </message>
        <message>
            <source>Name</source>
            <translation>名前</translation>
        </message>
        <message>
            <source>Type</source>
            <translation>種類</translation>
        </message>
        <message>
            <source>Ø mm</source>
            <translation>Ø mm</translation>
        </message>
        <message>
            <source>Corner r</source>
            <translation>コーナ r</translation>
        </message>
        <message>
            <source>Taper °</source>
            <translation>テーパ °</translation>
        </message>
        <message>
            <source>Flutes</source>
            <translation>刃数</translation>
        </message>
        <message>
            <source>Flute mm</source>
            <translation>刃長 mm</translation>
        </message>
        <message>
            <source>Stick-out mm</source>
            <translation>突出し mm</translation>
        </message>
        <message>
            <source>Holder</source>
            <translation>ホルダ</translation>
        </message>
        <message>
            <source>Holder Ø mm</source>
            <translation>ホルダ Ø mm</translation>
        </message>
        <message>
            <source>Life min</source>
            <translation>寿命 分</translation>
        </message>
        <message>
            <source>Used min</source>
            <translation>使用 分</translation>
        </message>
        <message>
            <source>&amp;Copy</source>
            <translation>複製(&amp;C)</translation>
        </message>
        <message>
            <source>Re&amp;tire</source>
            <translation>廃棄(&amp;T)</translation>
        </message>
        <message>
            <source>&amp;Undo</source>
            <translation>元に戻す(&amp;U)</translation>
        </message>
        <message>
            <source>&amp;Export tool table…</source>
            <translation>工具テーブルを書き出し(&amp;E)…</translation>
        </message>
        <message numerus="yes">
            <source>%1 — %n tool(s)</source>
            <translation>
                <numerusform>%1 — %n 本の工具</numerusform>
            </translation>
        </message>
        <message>
            <source>Cannot read the tool library: %1</source>
            <translation>工具ライブラリを読めません: %1</translation>
        </message>
        <message>
            <source>Select a tool first.</source>
            <translation>先に工具を選んでください。</translation>
        </message>
        <message>
            <source>T%1 not saved: %2 '%3' is not a number</source>
            <translation>T%1 は保存されませんでした: %2 の「%3」は数値ではありません</translation>
        </message>
        <message>
            <source>T%1: %2 changed</source>
            <translation>T%1: %2 を変更しました</translation>
        </message>
        <message>
            <source>No free T number: the library uses T%1</source>
            <translation>空き T 番号がありません: ライブラリは T%1 まで使用しています</translation>
        </message>
        <message>
            <source>T%1 copied to T%2</source>
            <translation>T%1 を T%2 に複製しました</translation>
        </message>
        <message>
            <source>T%1 retired (Undo brings it back)</source>
            <translation>T%1 を廃棄しました (元に戻すで復帰)</translation>
        </message>
        <message>
            <source>T%1: wear reset</source>
            <translation>T%1: 摩耗をリセットしました</translation>
        </message>
        <message>
            <source>Cannot write %1: %2</source>
            <translation>%1 に書き込めません: %2</translation>
        </message>
        <message>
            <source>Tool table written to %1</source>
            <translation>工具テーブルを %1 に書き出しました</translation>
        </message>
        <message>
            <source>LinuxCNC tool table (*.tbl)</source>
            <translation>LinuxCNC 工具テーブル (*.tbl)</translation>
        </message>
        <message>
            <source>FANUC offset program, G10 (*.nc)</source>
            <translation>FANUC オフセットプログラム、G10 (*.nc)</translation>
        </message>
        <message>
            <source>Export tool table</source>
            <translation>工具テーブルの書き出し</translation>
        </message>
        <message>
            <source>%1, Ø %2 mm, %3 flutes, stick-out %4 mm, holder %5, used %6 of %7 min</source>
            <translation>%1、Ø %2 mm、刃数 %3、突き出し %4 mm、ホルダー %5、使用 %6 / %7 分</translation>
        </message>
        <message>
            <source>Cannot retire the tool: %1</source>
            <translation>工具を廃棄できません: %1</translation>
        </message>
        <message>
            <source>Cannot save the tool: %1</source>
            <translation>工具を保存できません: %1</translation>
        </message>
        <message>
            <source>Tool changed meanwhile</source>
            <translation>工具が変更されています</translation>
        </message>
        <message>
            <source>T%1 was changed by %2 at station %3 (%4) after this station read it.

Yours: %5
Theirs: %6</source>
            <translation>T%1 はこのステーションが読み込んだ後に %2 によりステーション %3 で変更されました（%4）。

こちら: %5
相手: %6</translation>
        </message>
        <message>
            <source>removed</source>
            <translation>削除済み</translation>
        </message>
        <message>
            <source>Keep mine</source>
            <translation>こちらを残す</translation>
        </message>
        <message>
            <source>Take theirs</source>
            <translation>相手のものを採用</translation>
        </message>
        <message>
            <source>T%1 was changed again meanwhile; nothing saved</source>
            <translation>T%1 はその間に再び変更されました。保存していません</translation>
        </message>
        <message>
            <source>T%1: theirs taken, yours not saved</source>
            <translation>T%1: 相手のものを採用しました。こちらの変更は保存していません</translation>
        </message>
        <message>
            <source>Cannot open the tool library: %1</source>
            <translation>工具ライブラリを開けません: %1</translation>
        </message>
        <message numerus="yes">
            <source>This changes %n step(s) of the open job:</source>
            <translation>
                <numerusform>この変更で開いているジョブの %n 個の工程が変わります:</numerusform>
            </translation>
        </message>
        <message>
            <source>no tool</source>
            <translation>工具なし</translation>
        </message>
        <message>
            <source>unit %1, %2</source>
            <translation>ユニット %1、%2</translation>
        </message>
        <message>
            <source>  %1: %2, its data changed</source>
            <translation>  %1: %2 (工具データが変わります)</translation>
        </message>
        <message>
            <source>  %1: no tool</source>
            <translation>  %1: 工具なし</translation>
        </message>
        <message>
            <source>  %1: %2 → %3</source>
            <translation>  %1: %2 → %3</translation>
        </message>
        <message>
            <source>The job would be refused:</source>
            <translation>ジョブは受け付けられなくなります:</translation>
        </message>
        <message>
            <source>T%1: %2 %3 → %4</source>
            <translation>T%1: %2 %3 → %4</translation>
        </message>
        <message>
            <source>T%1: %2</source>
            <translation>T%1: %2</translation>
        </message>
        <message>
            <source>Apply the change?</source>
            <translation>変更を適用しますか?</translation>
        </message>
        <message>
            <source>T%1 not saved: %2</source>
            <translation>T%1 は保存されませんでした: %2</translation>
        </message>
        <message>
            <source>Change the tool?</source>
            <translation>工具を変更しますか?</translation>
        </message>
        <message>
            <source>T%1 not changed</source>
            <translation>T%1 は変更されませんでした</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::TwoPathChart</name>
        <message>
            <source>Path %1 (%2)</source>
            <translation>系統 %1（%2）</translation>
        </message>
        <message>
            <source>CB%1 in, dwell %2 s</source>
            <translation>CB%1 進入、ドウェル %2 秒</translation>
        </message>
        <message>
            <source>CB%1 in</source>
            <translation>CB%1 進入</translation>
        </message>
        <message>
            <source>CB%1 cut</source>
            <translation>CB%1 切削</translation>
        </message>
        <message>
            <source>CB%1 out</source>
            <translation>CB%1 退避</translation>
        </message>
        <message>
            <source>M%1 wait</source>
            <translation>M%1 待ち</translation>
        </message>
        <message>
            <source>M%1 met</source>
            <translation>M%1 同期</translation>
        </message>
        <message>
            <source>back to the safe point, end wait</source>
            <translation>安全点へ戻り、終了待ち</translation>
        </message>
        <message>
            <source>No balanced roughing on the timeline</source>
            <translation>タイムライン上にバランス荒加工なし</translation>
        </message>
        <message>
            <source>%1 s on %2 paths</source>
            <translation>%2 系統で %1 秒</translation>
        </message>
        <message>
            <source>Path %1: %2, %3–%4 s</source>
            <translation>系統 %1: %2、%3–%4 秒</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::TwoPathSteps</name>
        <message>
            <source>Path, step</source>
            <translation>系統・工程</translation>
        </message>
        <message>
            <source>Tool</source>
            <translation>工具</translation>
        </message>
        <message>
            <source>Time</source>
            <translation>時間</translation>
        </message>
        <message>
            <source>Path %1 (%2): turret with %3</source>
            <translation>系統 %1（%2）: タレットに %3</translation>
        </message>
        <message>
            <source>no tool</source>
            <translation>工具なし</translation>
        </message>
        <message>
            <source>%1, balanced: %2</source>
            <translation>%1、バランス: %2</translation>
        </message>
        <message>
            <source>CB%1: cut %2–%3 s</source>
            <translation>CB%1: 切削 %2–%3 秒</translation>
        </message>
        <message>
            <source>wait M%1</source>
            <translation>待ち M%1</translation>
        </message>
        <message>
            <source>dwell %1 s</source>
            <translation>ドウェル %1 秒</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::TwoPathViews</name>
        <message>
            <source>No roughing step to balance between the paths: path 2 has no program.</source>
            <translation>系統間でバランスさせる荒加工工程がありません: 系統 2 のプログラムはありません。</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::UnitForm</name>
        <message>
            <source>optional, e.g. Pocket A</source>
            <translation>任意、例: ポケット A</translation>
        </message>
        <message>
            <source>Unit name</source>
            <translation>ユニット名</translation>
        </message>
        <message>
            <source>not a whole number</source>
            <translation>整数ではありません</translation>
        </message>
        <message>
            <source>not a number</source>
            <translation>数値ではありません</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::UnitListPanel</name>
        <message>
            <source>D&amp;uplicate</source>
            <translation>複製(&amp;U)</translation>
        </message>
        <message>
            <source>▲ U&amp;p</source>
            <translation>▲ 上へ(&amp;P)</translation>
        </message>
        <message>
            <source>▼ Do&amp;wn</source>
            <translation>▼ 下へ(&amp;W)</translation>
        </message>
        <message>
            <source>De&amp;lete</source>
            <translation>削除(&amp;L)</translation>
        </message>
        <message>
            <source>Add %1 unit</source>
            <translation>%1 ユニットを追加</translation>
        </message>
        <message>
            <source>Added where it overlaps another unit: the stock has no free place for it. Type its corners, or make the stock larger.</source>
            <translation>他のユニットと重なる位置に追加しました: 素材に空きがありません。角の座標を入力するか、素材を大きくしてください。</translation>
        </message>
        <message>
            <source>No unit added: the stock has no free place for it. Make the stock larger or a unit smaller, or move one.</source>
            <translation>ユニットを追加できません: 素材に空きがありません。素材を大きくするか、ユニットを小さくするか、移動してください。</translation>
        </message>
        <message>
            <source>Duplicate unit %1</source>
            <translation>ユニット %1 を複製</translation>
        </message>
        <message>
            <source>Move unit %1</source>
            <translation>ユニット %1 を移動</translation>
        </message>
        <message>
            <source>Delete unit %1</source>
            <translation>ユニット %1 を削除</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::VerificationPanel</name>
        <message>
            <source>&amp;Verify</source>
            <translation>検証(&amp;V)</translation>
        </message>
        <message>
            <source>Cut every step into the stock on a %1 mm grid and list gouges, collisions, rapids into stock, travel limits and material left</source>
            <translation>全工程を %1 mm の格子で素材に削り込み、削り込み過ぎ・干渉・早送りでの素材への突入・ストローク超過・削り残しを一覧にします</translation>
        </message>
        <message>
            <source>Colour &amp;map</source>
            <translation>カラーマップ(&amp;M)</translation>
        </message>
        <message>
            <source>Show the finished part in the 3-D view coloured by what the verification found</source>
            <translation>検証の結果で色分けした仕上がり形状を 3D ビューに表示</translation>
        </message>
        <message>
            <source>gouge</source>
            <translation>削り込み</translation>
        </message>
        <message>
            <source>at size</source>
            <translation>寸法どおり</translation>
        </message>
        <message>
            <source>up to %1 mm left</source>
            <translation>%1 mm 以下の削り残し</translation>
        </message>
        <message>
            <source>more left</source>
            <translation>それ以上の削り残し</translation>
        </message>
        <message>
            <source>Verifying…</source>
            <translation>検証中…</translation>
        </message>
        <message>
            <source>Not verified since the last change.</source>
            <translation>最後の変更以降、未検証です。</translation>
        </message>
        <message>
            <source>No plan to verify.</source>
            <translation>検証する加工計画がありません。</translation>
        </message>
        <message>
            <source>Not verified: %1</source>
            <translation>未検証: %1</translation>
        </message>
        <message>
            <source>Verified at %1 mm: clean.</source>
            <translation>%1 mm で検証済み: 問題なし。</translation>
        </message>
        <message>
            <source>Verified at %1 mm: %2 faults, %3 with material left.</source>
            <translation>%1 mm で検証済み: 不具合 %2 件、削り残し %3 件。</translation>
        </message>
    </context>
    <context>
        <name>taiwa::CoreTexts</name>
        <message>
            <source>Pilot hole</source>
            <translation>下穴</translation>
        </message>
        <message>
            <source>Roughing</source>
            <translation>荒加工</translation>
        </message>
        <message>
            <source>Floor finishing</source>
            <translation>底面仕上げ</translation>
        </message>
        <message>
            <source>Wall finishing</source>
            <translation>側壁仕上げ</translation>
        </message>
        <message>
            <source>Inclined-face finishing</source>
            <translation>傾斜面仕上げ</translation>
        </message>
        <message>
            <source>Facing</source>
            <translation>端面削り</translation>
        </message>
        <message>
            <source>Centre drilling</source>
            <translation>センタ穴加工</translation>
        </message>
        <message>
            <source>Drilling</source>
            <translation>穴あけ</translation>
        </message>
        <message>
            <source>Grooving</source>
            <translation>溝入れ</translation>
        </message>
        <message>
            <source>Finishing</source>
            <translation>仕上げ</translation>
        </message>
        <message>
            <source>Threading</source>
            <translation>ねじ切り</translation>
        </message>
        <message>
            <source>Parting off</source>
            <translation>突切り</translation>
        </message>
        <message>
            <source>Tapping</source>
            <translation>タップ立て</translation>
        </message>
        <message>
            <source>Reaming</source>
            <translation>リーマ加工</translation>
        </message>
        <message>
            <source>Boring</source>
            <translation>中ぐり</translation>
        </message>
        <message>
            <source>roughing, floor finishing and wall finishing</source>
            <translation>荒加工、底面仕上げ、側壁仕上げ</translation>
        </message>
        <message>
            <source>roughing and floor finishing, walls left as roughed</source>
            <translation>荒加工と底面仕上げ、側壁は荒加工のまま</translation>
        </message>
        <message>
            <source>floor and wall finishing of a pocket already cored</source>
            <translation>下加工済みポケットの底面・側壁仕上げ</translation>
        </message>
        <message>
            <source>wall finishing only</source>
            <translation>側壁仕上げのみ</translation>
        </message>
        <message>
            <source>roughing only</source>
            <translation>荒加工のみ</translation>
        </message>
        <message>
            <source>walls finished to full depth in one incision</source>
            <translation>側壁を全深さで一度に仕上げ</translation>
        </message>
        <message>
            <source>walls finished in several Z incisions down to the floor</source>
            <translation>側壁を Z 方向に数回に分けて底まで仕上げ</translation>
        </message>
        <message>
            <source>walls semi-finished leaving alpha3, then finished</source>
            <translation>側壁を α3 残して中仕上げ後、仕上げ</translation>
        </message>
        <message>
            <source>drill a pilot hole first</source>
            <translation>先に下穴をあける</translation>
        </message>
        <message>
            <source>no pilot hole, the roughing tool ramps in</source>
            <translation>下穴なし、荒加工工具が斜めに切り込む</translation>
        </message>
        <message>
            <source>round (boss or bore)</source>
            <translation>丸形 (ボスまたは穴)</translation>
        </message>
        <message>
            <source>rectangular (block or pocket)</source>
            <translation>角形 (ブロックまたはポケット)</translation>
        </message>
        <message>
            <source>outside (boss, block)</source>
            <translation>外側 (ボス、ブロック)</translation>
        </message>
        <message>
            <source>inside (bore, pocket)</source>
            <translation>内側 (穴、ポケット)</translation>
        </message>
        <message>
            <source>(round: none)</source>
            <translation>(丸形：なし)</translation>
        </message>
        <message>
            <source>outer (OD)</source>
            <translation>外径 (OD)</translation>
        </message>
        <message>
            <source>inner (ID, a bore)</source>
            <translation>内径 (ID、穴)</translation>
        </message>
        <message>
            <source>Face milling</source>
            <translation>正面フライス削り</translation>
        </message>
        <message>
            <source>Side milling</source>
            <translation>側面削り</translation>
        </message>
        <message>
            <source>Area clearing</source>
            <translation>領域加工</translation>
        </message>
        <message>
            <source>roughing layers and a finishing pass</source>
            <translation>荒加工層と仕上げパス</translation>
        </message>
        <message>
            <source>roughing only, the finishing pass left</source>
            <translation>荒加工のみ、仕上げ分を残す</translation>
        </message>
        <message>
            <source>one way, every pass climb</source>
            <translation>一方向、全パスをダウンカット</translation>
        </message>
        <message>
            <source>zigzag, back and forth</source>
            <translation>ジグザグ、往復</translation>
        </message>
        <message>
            <source>left of the contour</source>
            <translation>輪郭の左側</translation>
        </message>
        <message>
            <source>right of the contour</source>
            <translation>輪郭の右側</translation>
        </message>
        <message>
            <source>climb</source>
            <translation>ダウンカット</translation>
        </message>
        <message>
            <source>conventional</source>
            <translation>アップカット</translation>
        </message>
        <message>
            <source>roughing and finishing</source>
            <translation>荒加工と仕上げ</translation>
        </message>
        <message>
            <source>finishing only</source>
            <translation>仕上げのみ</translation>
        </message>
        <message>
            <source>full depth at once</source>
            <translation>全深さで一度に</translation>
        </message>
        <message>
            <source>several incisions</source>
            <translation>深さを分けて数回</translation>
        </message>
        <message>
            <source>single</source>
            <translation>単独穴</translation>
        </message>
        <message>
            <source>line</source>
            <translation>直線配列</translation>
        </message>
        <message>
            <source>grid</source>
            <translation>格子配列</translation>
        </message>
        <message>
            <source>bolt circle</source>
            <translation>円周配列 (PCD)</translation>
        </message>
        <message>
            <source>arc</source>
            <translation>円弧配列</translation>
        </message>
        <message>
            <source>drilled</source>
            <translation>ドリル穴</translation>
        </message>
        <message>
            <source>tapped</source>
            <translation>タップ穴</translation>
        </message>
        <message>
            <source>reamed</source>
            <translation>リーマ穴</translation>
        </message>
        <message>
            <source>bored</source>
            <translation>中ぐり穴</translation>
        </message>
        <message>
            <source>the library has no tools</source>
            <translation>ライブラリに工具がありません</translation>
        </message>
        <message>
            <source>axes %1 mm</source>
            <translation>軸 %1 mm</translation>
        </message>
    </context>
    <context>
        <name>taiwa::Field</name>
        <message>
            <source>figure</source>
            <translation>図形</translation>
        </message>
        <message>
            <source>workOffset</source>
            <translation>ワーク座標系</translation>
        </message>
        <message>
            <source>stock</source>
            <translation>素材</translation>
        </message>
        <message>
            <source>clamping</source>
            <translation>クランプ</translation>
        </message>
        <message>
            <source>technology</source>
            <translation>加工条件</translation>
        </message>
        <message>
            <source>name</source>
            <translation>名前</translation>
        </message>
        <message>
            <source>material</source>
            <translation>材質</translation>
        </message>
        <message>
            <source>machine</source>
            <translation>機械</translation>
        </message>
        <message>
            <source>dialect</source>
            <translation>NC 形式</translation>
        </message>
        <message>
            <source>lengthUnit</source>
            <translation>長さの単位</translation>
        </message>
        <message>
            <source>format</source>
            <translation>形式</translation>
        </message>
        <message>
            <source>version</source>
            <translation>バージョン</translation>
        </message>
        <message>
            <source>units</source>
            <translation>ユニット</translation>
        </message>
        <message>
            <source>latheRoughing</source>
            <translation>旋削荒加工</translation>
        </message>
        <message>
            <source>height</source>
            <translation>高さ</translation>
        </message>
        <message>
            <source>width</source>
            <translation>幅</translation>
        </message>
        <message>
            <source>length</source>
            <translation>長さ</translation>
        </message>
        <message>
            <source>diameter</source>
            <translation>直径</translation>
        </message>
        <message>
            <source>face</source>
            <translation>端面</translation>
        </message>
        <message>
            <source>bore</source>
            <translation>内径</translation>
        </message>
        <message>
            <source>shape</source>
            <translation>形状</translation>
        </message>
        <message>
            <source>fixture</source>
            <translation>治具</translation>
        </message>
        <message>
            <source>grip</source>
            <translation>つかみ方向</translation>
        </message>
        <message>
            <source>touches</source>
            <translation>タッチ点</translation>
        </message>
        <message>
            <source>cutting</source>
            <translation>切削条件</translation>
        </message>
        <message>
            <source>module</source>
            <translation>モジュール</translation>
        </message>
        <message>
            <source>unit</source>
            <translation>ユニット</translation>
        </message>
    </context>
    <context>
        <name>taiwa::PathNames</name>
        <message>
            <source>upper turret</source>
            <translation>上タレット</translation>
        </message>
        <message>
            <source>lower turret</source>
            <translation>下タレット</translation>
        </message>
    </context>
    <context>
        <name>taiwa::msg</name>
        <message>
            <source>the library has no tools</source>
            <translation>工具ライブラリに工具がありません</translation>
        </message>
        <message>
            <source>T{} ({} {}, nose R{} mm)</source>
            <translation>T{} ({} {}, ノーズR{} mm)</translation>
        </message>
        <message>
            <source>T{} ({} Ø{} mm, {} per side)</source>
            <translation>T{} ({} Ø{} mm, 片側 {})</translation>
        </message>
        <message>
            <source>T{} ({} Ø{} mm)</source>
            <translation>T{} ({} Ø{} mm)</translation>
        </message>
        <message>
            <source>{} is not a finite number; type a number</source>
            <translation>{} が有限の数ではありません。数値を入力してください</translation>
        </message>
        <message>
            <source>material "{}" is not in the technology table; known materials: {}</source>
            <translation>材質「{}」は加工条件表にありません。登録済みの材質: {}</translation>
        </message>
        <message>
            <source>the stock {} is {}; it must be greater than zero</source>
            <translation>素材の{}が {} です。0 より大きくしてください</translation>
        </message>
        <message>
            <source>{} = {}{} must be greater than zero</source>
            <translation>{} = {}{} は 0 より大きくしてください</translation>
        </message>
        <message>
            <source>the pilot-hole remainder α1 = {} is not smaller than the depth {} of unit {}: the pilot hole would have no depth; use H = 9 or a smaller α1</source>
            <translation>下穴の残し α1 = {0} がユニット {2} の深さ {1} より小さくありません。下穴の深さがなくなります。H = 9 にするか α1 を小さくしてください</translation>
        </message>
        <message>
            <source>the floor allowance β2 = {} is not smaller than the depth {} of unit {}: roughing would not cut at all</source>
            <translation>底の仕上げ代 β2 = {0} がユニット {2} の深さ {1} より小さくありません。荒加工でまったく削れません</translation>
        </message>
        <message>
            <source>{} is {}; every length and coordinate must lie within ±{} of the origin (beyond it a micrometre is no longer exact on the tape)</source>
            <translation>{} が {} です。長さと座標はすべて原点から ±{} 以内にしてください (それを超えるとテープ上で 1 µm が正確に表せません)</translation>
        </message>
        <message>
            <source>{} is {:g}{}; it must lie between {:g} and {:g}{} ({})</source>
            <translation>{} が {}{} です。{} から {}{} の間にしてください ({})</translation>
        </message>
        <message>
            <source>the stock {} is {}; a stock of more than {} a side is not a part for this station</source>
            <translation>素材の{}が {} です。一辺が {} を超える素材はこのステーションでは扱いません</translation>
        </message>
        <message>
            <source>the depth is {}; it must be greater than zero (measured down from the top face)</source>
            <translation>深さが {} です。0 より大きくしてください (上面から下へ測ります)</translation>
        </message>
        <message>
            <source>the depth {} is deeper than the stock, which is {} high</source>
            <translation>深さ {} が素材の高さ {} より深くなっています</translation>
        </message>
        <message>
            <source>{} is {}; it must be greater than zero</source>
            <translation>{} が {} です。0 より大きくしてください</translation>
        </message>
        <message>
            <source>the figure of unit {} overlaps the figure of unit {} by {} {}²; figures of one job may touch but not overlap</source>
            <translation>ユニット {} の図形がユニット {} の図形と {} {}² 重なっています。同じジョブの図形は接してもよいが重なってはいけません</translation>
        </message>
        <message>
            <source>"{}" is not a step of module {}; its steps are {}</source>
            <translation>「{}」はモジュール {} の工程ではありません。工程は {} です</translation>
        </message>
        <message>
            <source>module {} has no cutting steps to set a speed or feed for</source>
            <translation>モジュール {} には回転数や送りを設定する切削工程がありません</translation>
        </message>
        <message>
            <source>{} {:g} {} is out of range: give {:g} to {:g} {}{}</source>
            <translation>{} {} {} が範囲外です。{} ～ {} {} にしてください{}</translation>
        </message>
        <message>
            <source>tool T{} is not in the tool library</source>
            <translation>工具 T{} が工具ライブラリにありません</translation>
        </message>
        <message>
            <source>the tool library has no {}; add one to machine this pocket</source>
            <translation>工具ライブラリに{}がありません。このポケットを加工するには追加してください</translation>
        </message>
        <message>
            <source>no taper end mill of {} per side in the tool library (it has none)</source>
            <translation>片側 {} のテーパエンドミルが工具ライブラリにありません (テーパエンドミルは 1 本もありません)</translation>
        </message>
        <message>
            <source>no taper end mill of {} per side in the tool library (it has {})</source>
            <translation>片側 {} のテーパエンドミルが工具ライブラリにありません (あるのは {})</translation>
        </message>
        <message>
            <source>{} = {} is smaller than the radius of the smallest suitable tool, {}; no tool of the library fits: a corner radius of at least {} would let it fit</source>
            <translation>{} = {} が使える最小の工具 {} の半径より小さくなっています。ライブラリのどの工具も入りません。コーナ半径を {} 以上にすれば入ります</translation>
        </message>
        <message>
            <source>{} would fit</source>
            <translation>{} なら入ります</translation>
        </message>
        <message>
            <source>no tool of that kind in the library fits</source>
            <translation>ライブラリにはその種類で入る工具がありません</translation>
        </message>
        <message>
            <source>the {} tool {} is too big for {} = {}; {}</source>
            <translation>{}の工具 {} は {} = {} に対して大きすぎます。{}</translation>
        </message>
        <message>
            <source>the step-over</source>
            <translation>横送り</translation>
        </message>
        <message>
            <source>{}, {}</source>
            <translation>{}, {}</translation>
        </message>
        <message>
            <source>more than {} ends meet at {} or near it: {}, …; the nearest were joined, the rest left open</source>
            <translation>{1} またはその付近で {0} を超える端点が集まっています: {2}, …。最も近いものをつなぎ、残りは開いたままにしました</translation>
        </message>
        <message>
            <source>more than {} ends meet at {} or near it: {}; the nearest were joined, the rest left open</source>
            <translation>{1} またはその付近で {0} を超える端点が集まっています: {2}。最も近いものをつなぎ、残りは開いたままにしました</translation>
        </message>
        <message>
            <source>{} ends meet at {}: {}, …; the nearest were joined, the rest left open</source>
            <translation>{1} で {0} 個の端点が集まっています: {2}, …。最も近いものをつなぎ、残りは開いたままにしました</translation>
        </message>
        <message>
            <source>{} ends meet at {}: {}; the nearest were joined, the rest left open</source>
            <translation>{1} で {0} 個の端点が集まっています: {2}。最も近いものをつなぎ、残りは開いたままにしました</translation>
        </message>
        <message>
            <source>gap of {:.4g} mm at {} between {} and {}, whose end is at {}; the gap tolerance is {:.4g} mm</source>
            <translation>{1} で {2} と {3} (端点は {4}) の間に {0} mm の隙間があります。隙間の許容値は {5} mm です</translation>
        </message>
        <message>
            <source>its plane is not the XY plane (extrusion {:.4g}, {:.4g}, {:.4g})</source>
            <translation>平面が XY 平面ではありません (押し出し方向 {}, {}, {})</translation>
        </message>
        <message>
            <source>it leaves the XY plane (its ends differ in Z)</source>
            <translation>XY 平面から外れています (両端の Z が異なります)</translation>
        </message>
        <message>
            <source>{} not read: {}</source>
            <translation>{} は読み込みません: {}</translation>
        </message>
        <message>
            <source>it has no length</source>
            <translation>長さがありません</translation>
        </message>
        <message>
            <source>its radius {:g} is not positive</source>
            <translation>半径 {} が正ではありません</translation>
        </message>
        <message>
            <source>its major axis leaves the XY plane</source>
            <translation>長軸が XY 平面から外れています</translation>
        </message>
        <message>
            <source>it is degenerate (axis {:g}, ratio {:g})</source>
            <translation>退化しています (軸 {}、比 {})</translation>
        </message>
        <message>
            <source>its parameters are out of range</source>
            <translation>パラメータが範囲外です</translation>
        </message>
        <message>
            <source>it needs more than {} lines at the spline tolerance</source>
            <translation>スプライン許容値では {} 本を超える直線が必要です</translation>
        </message>
        <message>
            <source>it leaves the XY plane (its vertices differ in Z)</source>
            <translation>XY 平面から外れています (頂点の Z が異なります)</translation>
        </message>
        <message>
            <source>{}: a bulge of {:g} read as a straight line</source>
            <translation>{}: ふくらみ {} を直線として読み込みました</translation>
        </message>
        <message>
            <source>its {} vertices give no segment</source>
            <translation>{} 個の頂点から線分ができません</translation>
        </message>
        <message>
            <source>it is given by fit points only, without control points</source>
            <translation>制御点がなく、フィット点だけで定義されています</translation>
        </message>
        <message>
            <source>it has no control points</source>
            <translation>制御点がありません</translation>
        </message>
        <message>
            <source>its degree {} is not 1 to 20</source>
            <translation>次数 {} が 1 ～ 20 ではありません</translation>
        </message>
        <message>
            <source>{} knots do not fit {} control points of degree {}</source>
            <translation>ノット {0} 個は次数 {2} の制御点 {1} 個に合いません</translation>
        </message>
        <message>
            <source>its knots decrease</source>
            <translation>ノットが減少しています</translation>
        </message>
        <message>
            <source>its knots span nothing</source>
            <translation>ノットの範囲が空です</translation>
        </message>
        <message>
            <source>it leaves the XY plane (its control points differ in Z)</source>
            <translation>XY 平面から外れています (制御点の Z が異なります)</translation>
        </message>
        <message>
            <source>a weight {:g} is not positive</source>
            <translation>重み {} が正ではありません</translation>
        </message>
        <message>
            <source>the drawing needs more than {} segments: too large or too fine a spline tolerance</source>
            <translation>図面には {} を超える線分が必要です: 大きすぎるか、スプライン許容値が細かすぎます</translation>
        </message>
        <message>
            <source>inch</source>
            <translation>インチ</translation>
        </message>
        <message>
            <source>foot</source>
            <translation>フィート</translation>
        </message>
        <message>
            <source>mile</source>
            <translation>マイル</translation>
        </message>
        <message>
            <source>microinch</source>
            <translation>マイクロインチ</translation>
        </message>
        <message>
            <source>mil</source>
            <translation>ミル</translation>
        </message>
        <message>
            <source>yard</source>
            <translation>ヤード</translation>
        </message>
        <message>
            <source>ångström</source>
            <translation>オングストローム</translation>
        </message>
        <message>
            <source>none</source>
            <translation>なし</translation>
        </message>
        <message>
            <source>the gap tolerance {:g} mm is not between 0.000001 and 10 mm</source>
            <translation>隙間の許容値 {} mm が 0.000001 ～ 10 mm の範囲外です</translation>
        </message>
        <message>
            <source>the spline tolerance {:g} mm is not between 0.0001 and 10 mm</source>
            <translation>スプライン許容値 {} mm が 0.0001 ～ 10 mm の範囲外です</translation>
        </message>
        <message>
            <source>the gap report distance {:g} mm is not between 0 and 1000 mm</source>
            <translation>隙間を報告する距離 {} mm が 0 ～ 1000 mm の範囲外です</translation>
        </message>
        <message>
            <source>{} on layer {} (DXF line {})</source>
            <translation>レイヤ {1} の {0} (DXF {2} 行目)</translation>
        </message>
        <message>
            <source>{} on layer {}</source>
            <translation>レイヤ {1} の {0}</translation>
        </message>
        <message>
            <source>cannot read {}: {}</source>
            <translation>{} を読めません: {}</translation>
        </message>
        <message>
            <source>{} is larger than 256 MB</source>
            <translation>{} は 256 MB より大きいです</translation>
        </message>
        <message>
            <source>cannot open {}: {}</source>
            <translation>{} を開けません: {}</translation>
        </message>
        <message>
            <source>cannot read {}</source>
            <translation>{} を読めません</translation>
        </message>
        <message>
            <source>the drawing has no layer {}</source>
            <translation>図面にレイヤ {} がありません</translation>
        </message>
        <message>
            <source>the drawing's units ($INSUNITS {}) are not lengths to machine in</source>
            <translation>図面の単位 ($INSUNITS {}) は加工に使える長さの単位ではありません</translation>
        </message>
        <message>
            <source>the drawing does not say its units ($INSUNITS unitless or absent): read as mm</source>
            <translation>図面に単位がありません ($INSUNITS が単位なしまたは未設定): mm として読み込みました</translation>
        </message>
        <message>
            <source>the drawing says its units are {}; read as {} as set</source>
            <translation>図面の単位は {} ですが、設定どおり {} として読み込みました</translation>
        </message>
        <message>
            <source>no lines, arcs, circles, polylines, splines or ellipses on the drawing's layers; the drawing's layers: {}</source>
            <translation>図面のレイヤに線・円弧・円・ポリライン・スプライン・楕円がありません。図面のレイヤ: {}</translation>
        </message>
        <message>
            <source>no lines, arcs, circles, polylines, splines or ellipses on the selected layers; the drawing's layers: {}</source>
            <translation>選んだレイヤに線・円弧・円・ポリライン・スプライン・楕円がありません。図面のレイヤ: {}</translation>
        </message>
        <message>
            <source>none of the entities on the selected layers could be read (see the warnings)</source>
            <translation>選んだレイヤの要素を一つも読み込めませんでした (警告を参照)</translation>
        </message>
        <message>
            <source>{} gaps up to {:.4g} mm closed (the largest at ({:.3f}, {:.3f})); the gap tolerance is {:.4g} mm</source>
            <translation>最大 {1} mm の隙間を {0} か所閉じました (最大のものは ({2}, {3}))。隙間の許容値は {4} mm です</translation>
        </message>
        <message>
            <source>… and {} more warnings like these</source>
            <translation>… ほかに同様の警告が {} 件</translation>
        </message>
        <message>
            <source>line {}: '{}' stands where a DXF group code belongs: not a DXF file, or a damaged one</source>
            <translation>{0} 行目: DXF のグループコードの位置に '{1}' があります。DXF ファイルでないか、壊れています</translation>
        </message>
        <message>
            <source>{} entities in paper space not read</source>
            <translation>ペーパー空間の要素 {} 個は読み込みません</translation>
        </message>
        <message>
            <source>not read (no contour geometry): {} — block references are not expanded: explode them in the CAD program</source>
            <translation>読み込みません (輪郭の形状ではありません): {} — ブロック参照は展開しません。CAD で分解してください</translation>
        </message>
        <message>
            <source>not read (no contour geometry): {}</source>
            <translation>読み込みません (輪郭の形状ではありません): {}</translation>
        </message>
        <message>
            <source>line {}: POLYLINE without SEQEND, read up to its last VERTEX</source>
            <translation>{} 行目: SEQEND のない POLYLINE。最後の VERTEX まで読み込みました</translation>
        </message>
        <message>
            <source>line {}: POLYLINE mesh or polyface (flags {}) is no contour: not read</source>
            <translation>{} 行目: POLYLINE のメッシュまたはポリフェース (フラグ {}) は輪郭ではありません。読み込みません</translation>
        </message>
        <message>
            <source>line {}: {} not read: '{}' is not a finite number (within ±1e12)</source>
            <translation>{} 行目: {} は読み込みません: '{}' は有限の数値 (±1e12 以内) ではありません</translation>
        </message>
        <message>
            <source>line {}: {} not read: '{}' is not an integer</source>
            <translation>{} 行目: {} は読み込みません: '{}' は整数ではありません</translation>
        </message>
        <message>
            <source>line {}: SPLINE not read: {} weights for {} control points</source>
            <translation>{0} 行目: SPLINE は読み込みません: 制御点 {2} 個に重みが {1} 個です</translation>
        </message>
        <message>
            <source>the file is empty</source>
            <translation>ファイルが空です</translation>
        </message>
        <message>
            <source>the file is larger than {} MB</source>
            <translation>ファイルが {} MB より大きいです</translation>
        </message>
        <message>
            <source>a binary DXF: save the drawing as an ASCII DXF (R12 or later)</source>
            <translation>バイナリ DXF です: 図面を ASCII DXF (R12 以降) で保存してください</translation>
        </message>
        <message>
            <source>not a DXF file: it holds binary data</source>
            <translation>DXF ファイルではありません: バイナリデータを含んでいます</translation>
        </message>
        <message>
            <source>not a DXF file: it starts with '{}'</source>
            <translation>DXF ファイルではありません: '{}' で始まっています</translation>
        </message>
        <message>
            <source>not a DXF file: it has no SECTION</source>
            <translation>DXF ファイルではありません: SECTION がありません</translation>
        </message>
        <message>
            <source>the DXF file has no ENTITIES section</source>
            <translation>DXF ファイルに ENTITIES セクションがありません</translation>
        </message>
        <message>
            <source>the file ends in the middle of a group: it may be cut short</source>
            <translation>ファイルがグループの途中で終わっています: 途中で切れている可能性があります</translation>
        </message>
        <message>
            <source>the file ends without EOF: it may be cut short</source>
            <translation>ファイルが EOF なしで終わっています: 途中で切れている可能性があります</translation>
        </message>
        <message>
            <source>{}; nothing was changed in {}</source>
            <translation>{0}。{1} の中は何も変更していません</translation>
        </message>
        <message>
            <source>the job did not pass input processing; nothing was written</source>
            <translation>ジョブが入力処理を通りませんでした。何も書き出していません</translation>
        </message>
        <message>
            <source>{}; nothing was written</source>
            <translation>{}。何も書き出していません</translation>
        </message>
        <message>
            <source>unknown dialect '{}'; nothing was written</source>
            <translation>不明な NC 形式 '{}' です。何も書き出していません</translation>
        </message>
        <message>
            <source>cannot create folder {}: {}</source>
            <translation>フォルダ {} を作成できません: {}</translation>
        </message>
        <message>
            <source>no PDF to join</source>
            <translation>結合する PDF がありません</translation>
        </message>
        <message>
            <source>cannot join the sheet's PDF parts: {}</source>
            <translation>作業指示書の PDF の部分を結合できません: {}</translation>
        </message>
        <message>
            <source>cannot paint the instruction sheet's PDF</source>
            <translation>作業指示書の PDF を描画できません</translation>
        </message>
        <message>
            <source>it has no segments</source>
            <translation>線分がありません</translation>
        </message>
        <message>
            <source>a closed contour of one line</source>
            <translation>直線 1 本だけの閉じた輪郭です</translation>
        </message>
        <message>
            <source>it reaches {}, beyond the ±1000000 mm the figure text can write</source>
            <translation>{} に達し、図形テキストで書ける ±1000000 mm を超えています</translation>
        </message>
        <message>
            <source>the arc around {} has a radius of {:g} mm, which rounds to nothing</source>
            <translation>{} を中心とする円弧の半径 {} mm は丸めると 0 になります</translation>
        </message>
        <message>
            <source>an arc's radius is beyond the 1000000 mm the figure text can write</source>
            <translation>円弧の半径が図形テキストで書ける 1000000 mm を超えています</translation>
        </message>
        <message>
            <source>two of its lines no longer meet at {} once written to {:g} mm</source>
            <translation>{1} mm 単位で書くと二本の線が {0} で交わらなくなります</translation>
        </message>
        <message>
            <source>its elements cannot be evaluated: {}</source>
            <translation>要素を計算できません: {}</translation>
        </message>
        <message>
            <source>its elements {} and {} no longer meet at {} once written to {:g} mm</source>
            <translation>{3} mm 単位で書くと要素 {0} と {1} が {2} で交わらなくなります</translation>
        </message>
        <message>
            <source>{} and {} cross twice at {} within {:g} mm in x and in y: XLARGE, XSMALL, YLARGE and YSMALL cannot choose between the two</source>
            <translation>{0} と {1} は {2} 付近で x も y も {3} mm 以内の 2 点で交わります: XLARGE、XSMALL、YLARGE、YSMALL ではどちらか選べません</translation>
        </message>
        <message>
            <source>{} and {} are parallel: they do not meet</source>
            <translation>{} と {} は平行です: 交わりません</translation>
        </message>
        <message>
            <source>{} and {} are concentric: they do not meet</source>
            <translation>{} と {} は同心です: 交わりません</translation>
        </message>
        <message>
            <source>{} and {} do not meet</source>
            <translation>{} と {} は交わりません</translation>
        </message>
        <message>
            <source>{} and {} meet twice: write XLARGE, XSMALL, YLARGE or YSMALL before {} to choose</source>
            <translation>{0} と {1} は 2 回交わります: 選ぶには {2} の前に XLARGE、XSMALL、YLARGE または YSMALL を書いてください</translation>
        </message>
        <message>
            <source>{} cannot choose between the two junctions of {} and {}: both have the same x; use YLARGE or YSMALL</source>
            <translation>{0} では {1} と {2} の 2 つの接続点を選べません: x が同じです。YLARGE か YSMALL を使ってください</translation>
        </message>
        <message>
            <source>{} cannot choose between the two junctions of {} and {}: both have the same y; use XLARGE or XSMALL</source>
            <translation>{0} では {1} と {2} の 2 つの接続点を選べません: y が同じです。XLARGE か XSMALL を使ってください</translation>
        </message>
        <message>
            <source>{} is not on {}: an open contour starts on its first element</source>
            <translation>{} は {} の上にありません: 開いた輪郭は最初の要素の上で始まります</translation>
        </message>
        <message>
            <source>{} is not on {}: an open contour ends on its last element</source>
            <translation>{} は {} の上にありません: 開いた輪郭は最後の要素の上で終わります</translation>
        </message>
        <message>
            <source>its coordinates cannot be computed (a degenerate definition)</source>
            <translation>座標を計算できません (退化した定義)</translation>
        </message>
        <message>
            <source>{} is of zero length between {} and {}</source>
            <translation>{0} は {1} と {2} の間で長さが 0 です</translation>
        </message>
        <message>
            <source>ROUND {} between {} and {}</source>
            <translation>{1} と {2} の間の ROUND {0}</translation>
        </message>
        <message>
            <source>CHAMF {} between {} and {}</source>
            <translation>{1} と {2} の間の CHAMF {0}</translation>
        </message>
        <message>
            <source>{}: they meet tangentially, there is no corner</source>
            <translation>{}: 両者は接して交わり、角がありません</translation>
        </message>
        <message>
            <source>{}: {} turns back along {}, there is no corner</source>
            <translation>{0}: {1} が {2} に沿って折り返しており、角がありません</translation>
        </message>
        <message>
            <source>{} does not fit: it is not smaller than {}'s radius {}</source>
            <translation>{0} は入りません: {1} の半径 {2} より小さくありません</translation>
        </message>
        <message>
            <source>{} does not fit: no circle of radius {} touches both in the corner</source>
            <translation>{0} は入りません: 角で両方に接する半径 {1} の円がありません</translation>
        </message>
        <message>
            <source>{} does not fit: {} is {} mm long from the start {}</source>
            <translation>{0} は入りません: {1} は始点 {3} から {2} mm しかありません</translation>
        </message>
        <message>
            <source>{} does not fit: {} is {} mm long from the previous corner</source>
            <translation>{0} は入りません: {1} は前の角から {2} mm しかありません</translation>
        </message>
        <message>
            <source>{} does not fit: {} is {} mm long to the end {}</source>
            <translation>{0} は入りません: {1} は終点 {3} まで {2} mm しかありません</translation>
        </message>
        <message>
            <source>{} does not fit: {} is {} mm long to the next corner</source>
            <translation>{0} は入りません: {1} は次の角まで {2} mm しかありません</translation>
        </message>
        <message>
            <source>{} and {} coincide: no circle through three points</source>
            <translation>{} と {} が一致しています: 3 点を通る円がありません</translation>
        </message>
        <message>
            <source>{} cannot choose between the two {}: both have the same x; use YLARGE or YSMALL</source>
            <translation>{0} では 2 つの{1}を選べません: x が同じです。YLARGE か YSMALL を使ってください</translation>
        </message>
        <message>
            <source>{} cannot choose between the two {}: both have the same y; use XLARGE or XSMALL</source>
            <translation>{0} では 2 つの{1}を選べません: y が同じです。XLARGE か XSMALL を使ってください</translation>
        </message>
        <message>
            <source>{} names no side of {}: it is parallel to the X axis; use YLARGE or YSMALL</source>
            <translation>{0} では {1} の側を指定できません: X 軸に平行です。YLARGE か YSMALL を使ってください</translation>
        </message>
        <message>
            <source>{} names no side of {}: it is parallel to the Y axis; use XLARGE or XSMALL</source>
            <translation>{0} では {1} の側を指定できません: Y 軸に平行です。XLARGE か XSMALL を使ってください</translation>
        </message>
        <message>
            <source>{} and {} are parallel: they do not intersect</source>
            <translation>{} と {} は平行です: 交点がありません</translation>
        </message>
        <message>
            <source>{} and {} are concentric: they do not intersect</source>
            <translation>{} と {} は同心です: 交点がありません</translation>
        </message>
        <message>
            <source>{} and {} coincide: no line through them</source>
            <translation>{} と {} が一致しています: 両点を通る直線がありません</translation>
        </message>
        <message>
            <source>intersections of {} and {}</source>
            <translation>{} と {} の交点</translation>
        </message>
        <message>
            <source>{} is inside {}: no tangent from it</source>
            <translation>{} は {} の内側にあります: そこから接線を引けません</translation>
        </message>
        <message>
            <source>{} and {} are concentric: no common tangent</source>
            <translation>{} と {} は同心です: 共通接線がありません</translation>
        </message>
        <message>
            <source>{} and {} lie one inside the other: no tangent on the same side of both</source>
            <translation>{} と {} は一方が他方の内側にあります: 両方の同じ側に接する接線がありません</translation>
        </message>
        <message>
            <source>{} and {} overlap: no tangent crossing between them</source>
            <translation>{} と {} は重なっています: 間を横切る接線がありません</translation>
        </message>
        <message>
            <source>{}, {} and {} lie on one line: no circle through them</source>
            <translation>{}、{}、{} は一直線上にあります: それらを通る円がありません</translation>
        </message>
        <message>
            <source>radius {} is not smaller than {}'s radius {}: no circle inside it</source>
            <translation>半径 {0} が {1} の半径 {2} より小さくありません: その内側に円は入りません</translation>
        </message>
        <message>
            <source>no circle of radius {} on the {} side of {} touches {} from outside (the radius is too small or the side is wrong)</source>
            <translation>{2} の {1} 側に、{3} に外側から接する半径 {0} の円がありません (半径が小さすぎるか、側が違います)</translation>
        </message>
        <message>
            <source>no circle of radius {} on the {} side of {} touches {} from inside (the radius is too small or the side is wrong)</source>
            <translation>{2} の {1} 側に、{3} に内側から接する半径 {0} の円がありません (半径が小さすぎるか、側が違います)</translation>
        </message>
        <message>
            <source>centres</source>
            <translation>中心</translation>
        </message>
        <message>
            <source>its text is refused: {}</source>
            <translation>テキストが受け付けられません: {}</translation>
        </message>
        <message>
            <source>its text gives back other segments</source>
            <translation>テキストから別の線分が戻ります</translation>
        </message>
        <message>
            <source>it comes back {:.7f} mm from the drawing</source>
            <translation>図面から {} mm ずれて戻ります</translation>
        </message>
        <message>
            <source>contour {} is left out: {}</source>
            <translation>輪郭 {} は除外しました: {}</translation>
        </message>
        <message>
            <source>contour {} ({}) comes back {:.7f} mm from the drawing</source>
            <translation>輪郭 {} ({}) は図面から {} mm ずれて戻ります</translation>
        </message>
        <message>
            <source>contour {} ({}) is written to {} mm: to 0.000001 mm {}</source>
            <translation>輪郭 {} ({}) は {} mm 単位で書きました: 0.000001 mm 単位では{}</translation>
        </message>
        <message>
            <source>a number</source>
            <translation>数値</translation>
        </message>
        <message>
            <source>a number (the y coordinate)</source>
            <translation>数値 (y 座標)</translation>
        </message>
        <message>
            <source>a circle name</source>
            <translation>円名</translation>
        </message>
        <message>
            <source>in {}, {} and {} may meet twice: write XLARGE, XSMALL, YLARGE or YSMALL before INTOF to choose</source>
            <translation>{0} で、{1} と {2} は 2 回交わることがあります: 選ぶには INTOF の前に XLARGE、XSMALL、YLARGE または YSMALL を書いてください</translation>
        </message>
        <message>
            <source>in {}, two lines meet once: no {} before INTOF</source>
            <translation>{} で、2 本の直線は 1 回しか交わりません: INTOF の前に {} は不要です</translation>
        </message>
        <message>
            <source>a number, CENTER, INTOF or XLARGE/XSMALL/YLARGE/YSMALL</source>
            <translation>数値、CENTER、INTOF または XLARGE/XSMALL/YLARGE/YSMALL</translation>
        </message>
        <message>
            <source>a line name</source>
            <translation>直線名</translation>
        </message>
        <message>
            <source>a number (the distance)</source>
            <translation>数値 (距離)</translation>
        </message>
        <message>
            <source>the distance</source>
            <translation>距離</translation>
        </message>
        <message>
            <source>a point name</source>
            <translation>点名</translation>
        </message>
        <message>
            <source>a number (the angle in degrees)</source>
            <translation>数値 (角度、度)</translation>
        </message>
        <message>
            <source>a point name, ATANGL, LEFT or RIGHT</source>
            <translation>点名、ATANGL、LEFT または RIGHT</translation>
        </message>
        <message>
            <source>a point name, PARLEL, LEFT or RIGHT</source>
            <translation>点名、PARLEL、LEFT または RIGHT</translation>
        </message>
        <message>
            <source>a line name, OUT or IN</source>
            <translation>直線名、OUT または IN</translation>
        </message>
        <message>
            <source>CENTER, a point name or XLARGE/XSMALL/YLARGE/YSMALL</source>
            <translation>CENTER、点名または XLARGE/XSMALL/YLARGE/YSMALL</translation>
        </message>
        <message>
            <source>a number (the radius)</source>
            <translation>数値 (半径)</translation>
        </message>
        <message>
            <source>the radius</source>
            <translation>半径</translation>
        </message>
        <message>
            <source>in {}, {} is not defined: an element must be defined before it is used</source>
            <translation>{0} で、{1} は定義されていません: 要素は使う前に定義してください</translation>
        </message>
        <message>
            <source>a line or circle name, CLW or CCLW</source>
            <translation>直線名または円名、CLW または CCLW</translation>
        </message>
        <message>
            <source>an element name, XLARGE/XSMALL/YLARGE/YSMALL, CLW or CCLW</source>
            <translation>要素名、XLARGE/XSMALL/YLARGE/YSMALL、CLW または CCLW</translation>
        </message>
        <message>
            <source>in {}, {} ends the contour but no point starts it: an open contour runs from a point to a point</source>
            <translation>{0} で、{1} が輪郭を終えていますが、始めの点がありません: 開いた輪郭は点から点までです</translation>
        </message>
        <message>
            <source>in {}, {} after {} is not between two elements: the contour ends at {}</source>
            <translation>{0} で、{2} の後の {1} が 2 つの要素の間にありません: 輪郭は {3} で終わります</translation>
        </message>
        <message>
            <source>in {}, {} is a point: only the first and the last item of a contour may be points</source>
            <translation>{0} で、{1} は点です: 点にできるのは輪郭の最初と最後の項目だけです</translation>
        </message>
        <message>
            <source>in {}, {} is {} where a circle is needed</source>
            <translation>{0} で、{1} は{2}ですが、ここには円が必要です</translation>
        </message>
        <message>
            <source>in {}, {} is {} where a line or a circle is needed</source>
            <translation>{0} で、{1} は{2}ですが、ここには直線か円が必要です</translation>
        </message>
        <message>
            <source>in {}, {} is a circle: write CLW or CCLW before it</source>
            <translation>{0} で、{1} は円です: その前に CLW か CCLW を書いてください</translation>
        </message>
        <message>
            <source>in {}, {} is a line: no {} before it (CLW and CCLW are for circles)</source>
            <translation>{0} で、{1} は直線です: その前に {2} は不要です (CLW と CCLW は円に使います)</translation>
        </message>
        <message>
            <source>in {}, {} follows itself: the same element twice in a row</source>
            <translation>{0} で、{1} が続けて 2 回あります: 同じ要素が連続しています</translation>
        </message>
        <message>
            <source>in {}, {} starts at {}: no {} before it</source>
            <translation>{0} で、{1} は {2} から始まります: その前に {3} は不要です</translation>
        </message>
        <message>
            <source>in {}, two lines meet once: no {} before {}</source>
            <translation>{0} で、2 本の直線は 1 回しか交わりません: {2} の前に {1} は不要です</translation>
        </message>
        <message>
            <source>a number (the chamfer)</source>
            <translation>数値 (面取り)</translation>
        </message>
        <message>
            <source>the chamfer</source>
            <translation>面取り</translation>
        </message>
        <message>
            <source>in {}, the contour starts at {} and needs a point at its end, on {}</source>
            <translation>{0} で、輪郭は {1} から始まるので、終わりに {2} の上の点が必要です</translation>
        </message>
        <message>
            <source>in {}, a closed contour needs two elements or more, or a single circle</source>
            <translation>{} で、閉じた輪郭には 2 つ以上の要素か、円 1 つが必要です</translation>
        </message>
        <message>
            <source>in {}, {} alone is a full circle: no {} before it</source>
            <translation>{0} で、{1} だけなので全円です: その前に {2} は不要です</translation>
        </message>
        <message>
            <source>in {}, {} alone is a full circle: no {} on it</source>
            <translation>{0} で、{1} だけなので全円です: {2} は付けられません</translation>
        </message>
        <message>
            <source>in {}, {} follows itself: the same element twice in a row (the last element joins the first)</source>
            <translation>{0} で、{1} が続けて 2 回あります: 同じ要素が連続しています (最後の要素は最初の要素につながります)</translation>
        </message>
        <message>
            <source>XLARGE, XSMALL, YLARGE or YSMALL</source>
            <translation>XLARGE、XSMALL、YLARGE または YSMALL</translation>
        </message>
        <message>
            <source>the end of the line</source>
            <translation>行末</translation>
        </message>
        <message>
            <source>the end of the text</source>
            <translation>テキストの終わり</translation>
        </message>
        <message>
            <source>the character '{}'</source>
            <translation>文字 '{}'</translation>
        </message>
        <message>
            <source>expected {} after {}, found {}</source>
            <translation>{1} の後には {0} が必要ですが、{2} があります</translation>
        </message>
        <message>
            <source>LEFT or RIGHT</source>
            <translation>LEFT または RIGHT</translation>
        </message>
        <message>
            <source>the number {} is out of range (at most 1000000 either way)</source>
            <translation>数値 {} が範囲外です (正負とも最大 1000000)</translation>
        </message>
        <message>
            <source>{} must be greater than 0, found {}</source>
            <translation>{}は 0 より大きくなければなりませんが、{}です</translation>
        </message>
        <message>
            <source>in {}, {} is {} where {} is needed</source>
            <translation>{0} で、{1} は{2}ですが、ここには{3}が必要です</translation>
        </message>
        <message>
            <source>a line or circle name</source>
            <translation>直線名または円名</translation>
        </message>
        <message>
            <source>expected an element name at the start of a statement, found {}</source>
            <translation>文の始めには要素名が必要ですが、{} があります</translation>
        </message>
        <message>
            <source>'{}' is a word of the language and cannot name an element</source>
            <translation>'{}' は言語の予約語なので要素名にできません</translation>
        </message>
        <message>
            <source>{} is already defined on line {}</source>
            <translation>{} は {} 行目ですでに定義されています</translation>
        </message>
        <message>
            <source>POINT, LINE, CIRCLE or CONTOUR</source>
            <translation>POINT、LINE、CIRCLE または CONTOUR</translation>
        </message>
        <message>
            <source>the end of the statement</source>
            <translation>文の終わり</translation>
        </message>
        <message>
            <source>a point</source>
            <translation>点</translation>
        </message>
        <message>
            <source>a line</source>
            <translation>直線</translation>
        </message>
        <message>
            <source>a circle</source>
            <translation>円</translation>
        </message>
        <message>
            <source>a contour</source>
            <translation>輪郭</translation>
        </message>
        <message>
            <source>cannot write {}: {}</source>
            <translation>{} に書き込めません: {}</translation>
        </message>
        <message>
            <source>the file changed while it was read</source>
            <translation>読み込み中にファイルが変更されました</translation>
        </message>
        <message>
            <source>cannot create a file in {}: {}</source>
            <translation>{} にファイルを作成できません: {}</translation>
        </message>
        <message>
            <source>cannot create the lock file {}: {}</source>
            <translation>ロックファイル {} を作成できません: {}</translation>
        </message>
        <message>
            <source>cannot lock {}: {}</source>
            <translation>{} をロックできません: {}</translation>
        </message>
        <message>
            <source>a string ({})</source>
            <translation>文字列 ({})</translation>
        </message>
        <message>
            <source>null</source>
            <translation>null</translation>
        </message>
        <message>
            <source>an object</source>
            <translation>オブジェクト</translation>
        </message>
        <message>
            <source>an array</source>
            <translation>配列</translation>
        </message>
        <message>
            <source>a string</source>
            <translation>文字列</translation>
        </message>
        <message>
            <source>a boolean</source>
            <translation>真偽値</translation>
        </message>
        <message>
            <source>an unexpected value</source>
            <translation>想定外の値</translation>
        </message>
        <message>
            <source>one of {}</source>
            <translation>{} のいずれか</translation>
        </message>
        <message>
            <source>the file is {} bytes ({:.1f} MB); a job file may be at most {} bytes ({} MB)</source>
            <translation>ファイルが {} バイト ({} MB) です。ジョブファイルは最大 {} バイト ({} MB) です</translation>
        </message>
        <message>
            <source>cannot open: {}</source>
            <translation>開けません: {}</translation>
        </message>
        <message>
            <source>cannot read the file: {}</source>
            <translation>ファイルを読めません: {}</translation>
        </message>
        <message>
            <source>not a regular file; a job file is a JSON document</source>
            <translation>通常のファイルではありません。ジョブファイルは JSON 文書です</translation>
        </message>
        <message>
            <source>not a job file: JSON syntax error at byte {} (line {}, column {}): {}</source>
            <translation>ジョブファイルではありません: {} バイト目 ({} 行 {} 列) に JSON の構文エラー: {}</translation>
        </message>
        <message>
            <source>not a job file: arrays and objects nested more than {} deep at byte {} (line {}, column {})</source>
            <translation>ジョブファイルではありません: {1} バイト目 ({2} 行 {3} 列) で配列とオブジェクトが {0} 段より深く入れ子になっています</translation>
        </message>
        <message>
            <source>the number {} is too large for any dimension</source>
            <translation>数値 {} はどの寸法としても大きすぎます</translation>
        </message>
        <message>
            <source>not a job file: the document is {}, a job is a JSON object</source>
            <translation>ジョブファイルではありません: 文書が{}です。ジョブは JSON オブジェクトです</translation>
        </message>
        <message>
            <source>not a job file: it has no "format": "taiwa-job"</source>
            <translation>ジョブファイルではありません: "format": "taiwa-job" がありません</translation>
        </message>
        <message>
            <source>not a job file: its "format" is {}, a job has "taiwa-job"</source>
            <translation>ジョブファイルではありません: "format" が{}です。ジョブは "taiwa-job" です</translation>
        </message>
        <message>
            <source>written by a newer Taiwa (format version {}); this program reads version {}</source>
            <translation>新しい Taiwa で書かれています (形式バージョン {})。このプログラムが読めるのはバージョン {} です</translation>
        </message>
        <message>
            <source>format version {} does not exist; this program reads version {}</source>
            <translation>形式バージョン {} はありません。このプログラムが読めるのはバージョン {} です</translation>
        </message>
        <message>
            <source>missing; it must be {}</source>
            <translation>ありません。{}が必要です</translation>
        </message>
        <message>
            <source>must be {}, found {}</source>
            <translation>{}でなければなりませんが、{}です</translation>
        </message>
        <message>
            <source>must be a whole number, found {}</source>
            <translation>整数でなければなりませんが、{}です</translation>
        </message>
        <message>
            <source>must be a whole number from -2147483648 to 2147483647, found {}</source>
            <translation>-2147483648 ～ 2147483647 の整数でなければなりませんが、{}です</translation>
        </message>
        <message>
            <source>unknown field; {} has {}</source>
            <translation>不明な項目です。{}にあるのは {} です</translation>
        </message>
        <message>
            <source>unknown module {}; this program knows {}</source>
            <translation>不明なモジュール {} です。このプログラムが知っているのは {} です</translation>
        </message>
        <message>
            <source>unknown stock shape {}; this program knows {}</source>
            <translation>不明な素材形状 {} です。このプログラムが知っているのは {} です</translation>
        </message>
        <message>
            <source>needs exactly four corner points P1..P4, found {}</source>
            <translation>角の点 P1..P4 がちょうど 4 つ必要ですが、{} 個あります</translation>
        </message>
        <message>
            <source>must be a point [x, y], found an array of {}</source>
            <translation>点 [x, y] でなければなりませんが、要素 {} 個の配列です</translation>
        </message>
        <message>
            <source>must be a point [x, y], found {}</source>
            <translation>点 [x, y] でなければなりませんが、{}です</translation>
        </message>
        <message>
            <source>given more than once; say it once so that it is clear which value counts</source>
            <translation>2 回以上指定されています。どの値が有効か明らかになるよう 1 回だけ指定してください</translation>
        </message>
        <message>
            <source>a whole number</source>
            <translation>整数</translation>
        </message>
        <message>
            <source>a point [x, y]</source>
            <translation>点 [x, y]</translation>
        </message>
        <message>
            <source>the jaws' height</source>
            <translation>バイスの口金の高さ</translation>
        </message>
        <message>
            <source>the surface speed S</source>
            <translation>切削速度 S</translation>
        </message>
        <message>
            <source>the spindle speed S</source>
            <translation>主軸回転数 S</translation>
        </message>
        <message>
            <source>the feed F</source>
            <translation>送り F</translation>
        </message>
        <message>
            <source>the follower's dwell is {:g} spindle revolutions; it must be at least 0.5, or the follower cuts where the leader has not</source>
            <translation>追従側のドウェルが主軸 {:g} 回転です。0.5 回転以上にしてください。でないと追従側が先行側のまだ削っていない所を削ります</translation>
        </message>
        <message>
            <source>machine {} has one path; the two-path settings are for a two-path lathe ({})</source>
            <translation>機械 {} は1系統です。2系統の設定は2系統旋盤（{}）のためのものです</translation>
        </message>
        <message>
            <source>M{} is not a wait code of machine {}: it waits with M{} to M{}</source>
            <translation>M{} は機械 {} の待ち合わせコードではありません。この機械の待ち合わせは M{}～M{} です</translation>
        </message>
        <message>
            <source>'{}' is not a work offset: give G54 to G59, G59.1 to G59.3, G54.1 P1 to P48 (G154 P on Haas) or G505 to G599 (SINUMERIK)</source>
            <translation>'{}' はワーク座標系ではありません: G54～G59、G59.1～G59.3、G54.1 P1～P48（Haas では G154 P）、または G505～G599（SINUMERIK）を指定してください</translation>
        </message>
        <message>
            <source>unknown dialect '{}'; this program posts {}</source>
            <translation>不明な NC 形式 '{}' です。このプログラムが出力できるのは {} です</translation>
        </message>
        <message>
            <source>the {} dialect writes no two-path programs; machine {} needs one of the ISO dialects</source>
            <translation>NC 形式 {} は2系統のプログラムを出力しません。機械 {} には ISO の NC 形式のいずれかが必要です</translation>
        </message>
        <message>
            <source>an object with S and/or F</source>
            <translation>S と F (どちらか一方でも可) を持つオブジェクト</translation>
        </message>
        <message>
            <source>a step's speed and feed</source>
            <translation>工程の回転数と送り</translation>
        </message>
        <message>
            <source>give S, F or both</source>
            <translation>S、F またはその両方を指定してください</translation>
        </message>
        <message>
            <source>a bar stock</source>
            <translation>棒材の素材</translation>
        </message>
        <message>
            <source>a block stock</source>
            <translation>ブロックの素材</translation>
        </message>
        <message>
            <source>an array of lines of figure-element text</source>
            <translation>図形要素のテキスト行の配列</translation>
        </message>
        <message>
            <source>a line of text</source>
            <translation>テキスト 1 行</translation>
        </message>
        <message>
            <source>a line of the figure holds a line break; give each line as its own string</source>
            <translation>図形の 1 行に改行が含まれています。各行を別々の文字列で指定してください</translation>
        </message>
        <message>
            <source>the clamping</source>
            <translation>クランプ</translation>
        </message>
        <message>
            <source>the two-path settings</source>
            <translation>2系統の設定</translation>
        </message>
        <message>
            <source>true or false</source>
            <translation>true または false</translation>
        </message>
        <message>
            <source>the technology overrides</source>
            <translation>加工条件の上書き</translation>
        </message>
        <message>
            <source>a job</source>
            <translation>ジョブ</translation>
        </message>
        <message>
            <source>an array of machining units</source>
            <translation>加工ユニットの配列</translation>
        </message>
        <message>
            <source>{} more warnings not listed</source>
            <translation>ほかに {} 件の警告があります（一覧にありません）</translation>
        </message>
        <message>
            <source>{} more errors not listed; correct the ones above first</source>
            <translation>ほかに {} 件のエラーがあります。まず上のものを直してください</translation>
        </message>
        <message>
            <source>pilot hole</source>
            <translation>下穴</translation>
        </message>
        <message>
            <source>roughing</source>
            <translation>荒加工</translation>
        </message>
        <message>
            <source>floor finishing</source>
            <translation>底面仕上げ</translation>
        </message>
        <message>
            <source>wall finishing</source>
            <translation>側壁仕上げ</translation>
        </message>
        <message>
            <source>inclined-face finishing</source>
            <translation>傾斜面仕上げ</translation>
        </message>
        <message>
            <source>facing</source>
            <translation>端面削り</translation>
        </message>
        <message>
            <source>centre drilling</source>
            <translation>センタ穴加工</translation>
        </message>
        <message>
            <source>drilling</source>
            <translation>穴あけ</translation>
        </message>
        <message>
            <source>grooving</source>
            <translation>溝入れ</translation>
        </message>
        <message>
            <source>finishing</source>
            <translation>仕上げ</translation>
        </message>
        <message>
            <source>threading</source>
            <translation>ねじ切り</translation>
        </message>
        <message>
            <source>parting off</source>
            <translation>突切り</translation>
        </message>
        <message>
            <source>tapping</source>
            <translation>タップ立て</translation>
        </message>
        <message>
            <source>reaming</source>
            <translation>リーマ加工</translation>
        </message>
        <message>
            <source>boring</source>
            <translation>中ぐり</translation>
        </message>
        <message>
            <source>face milling</source>
            <translation>正面フライス削り</translation>
        </message>
        <message>
            <source>side milling</source>
            <translation>側面削り</translation>
        </message>
        <message>
            <source>area clearing</source>
            <translation>領域加工</translation>
        </message>
        <message>
            <source>the wall allowance roughing leaves</source>
            <translation>荒加工が残す壁の仕上げ代</translation>
        </message>
        <message>
            <source>the wall allowance semi-finishing leaves</source>
            <translation>中仕上げが残す壁の仕上げ代</translation>
        </message>
        <message>
            <source>the floor allowance roughing leaves</source>
            <translation>荒加工が残す底の仕上げ代</translation>
        </message>
        <message>
            <source>centre drill</source>
            <translation>センタードリル</translation>
        </message>
        <message>
            <source>drill</source>
            <translation>ドリル</translation>
        </message>
        <message>
            <source>flat end mill</source>
            <translation>フラットエンドミル</translation>
        </message>
        <message>
            <source>ball end mill</source>
            <translation>ボールエンドミル</translation>
        </message>
        <message>
            <source>taper end mill</source>
            <translation>テーパエンドミル</translation>
        </message>
        <message>
            <source>face mill</source>
            <translation>正面フライス</translation>
        </message>
        <message>
            <source>turning insert</source>
            <translation>旋削チップ</translation>
        </message>
        <message>
            <source>grooving tool</source>
            <translation>溝入れバイト</translation>
        </message>
        <message>
            <source>threading tool</source>
            <translation>ねじ切りバイト</translation>
        </message>
        <message>
            <source>probe</source>
            <translation>タッチプローブ</translation>
        </message>
        <message>
            <source>tap</source>
            <translation>タップ</translation>
        </message>
        <message>
            <source>reamer</source>
            <translation>リーマ</translation>
        </message>
        <message>
            <source>boring bar</source>
            <translation>ボーリングバー</translation>
        </message>
        <message>
            <source>a point's X</source>
            <translation>点の X</translation>
        </message>
        <message>
            <source>a point's Y</source>
            <translation>点の Y</translation>
        </message>
        <message>
            <source>{} passes along an area of {} lines and arcs are more than the checks take ({:.3g} pass-segment pairs at most); draw fewer points, or simplify the area's contours</source>
            <translation>{} 本のパスと {} 本の線・円弧からなる領域は検査できる量を超えています（パスと要素の組は最大 {:.3g}）。点を減らすか、領域の輪郭を簡単にしてください</translation>
        </message>
        <message>
            <source>the {} passes' strips overlap in more than {} pairs: what they leave unswept is more than the checks take; draw fewer passes, or passes that cross each other less</source>
            <translation>{} 本のパスの帯が {} 組を超えて重なっています。削り残しの計算が検査できる量を超えます。パスを減らすか、交差の少ないパスを描いてください</translation>
        </message>
        <message>
            <source>the tool diameter</source>
            <translation>工具径</translation>
        </message>
        <message>
            <source>an array of points [x, y]</source>
            <translation>点 [x, y] の配列</translation>
        </message>
        <message>
            <source>'{}' is not a list of points; type each point as X, Y and separate the points with ';' (10, 20; 60, 20), or draw the passes in the Figure tab</source>
            <translation>「{}」は点の並びではありません。各点を X, Y で入力し、点どうしを ';' で区切るか (10, 20; 60, 20)、図形タブでパスを描いてください</translation>
        </message>
        <message>
            <source>no point is drawn; a pass runs from a start point to an end point: draw at least two points</source>
            <translation>点が描かれていません。パスは始点から終点まで走ります。少なくとも 2 点を描いてください</translation>
        </message>
        <message>
            <source>only one point is drawn; a pass runs from a start point to an end point: draw at least two points</source>
            <translation>描かれた点が 1 つだけです。パスは始点から終点まで走ります。少なくとも 2 点を描いてください</translation>
        </message>
        <message>
            <source>point {} ({}, {}) lies outside the stock</source>
            <translation>点 {} ({}, {}) が素材の外にあります</translation>
        </message>
        <message>
            <source>pass {} ends where it starts; remove the repeated point</source>
            <translation>パス {} が始点で終わっています。重複した点を削除してください</translation>
        </message>
        <message>
            <source>the start point ({}, {}) puts the tool's edge {} outside the area {} or into an island; start at least a tool radius inside</source>
            <translation>始点 ({0}, {1}) では工具の刃先が領域 {3} の外または島の中に {2} 入ります。少なくとも工具半径だけ内側から始めてください</translation>
        </message>
        <message>
            <source>pass {} takes the tool's edge {} outside the area {} (or into an island) with the tool's centre at ({}, {}); keep each pass a tool radius from the walls</source>
            <translation>パス {0} では工具中心が ({3}, {4}) のとき刃先が領域 {2} の外 (または島の中) に {1} 入ります。各パスを壁から工具半径だけ離してください</translation>
        </message>
        <message>
            <source>the tool diameter is {}; it must be positive: the passes are strips one tool wide</source>
            <translation>工具径が {} です。正の値にしてください。パスは工具 1 本分の幅の帯です</translation>
        </message>
        <message>
            <source>the library has no centre-cutting flat end mill of {} (nor of any diameter) for the drawn passes</source>
            <translation>描いたパス用の {} の (どの径の) センターカット付きフラットエンドミルも工具ライブラリにありません</translation>
        </message>
        <message>
            <source>the library has no centre-cutting flat end mill of {}, the width the passes were drawn for; its flat end mills: {}</source>
            <translation>パスを描いた幅 {} のセンターカット付きフラットエンドミルが工具ライブラリにありません。登録済みのフラットエンドミル: {}</translation>
        </message>
        <message>
            <source>{} is pinned, but the passes were drawn for a tool of {}; pin a tool of that diameter or change the diameter and redraw</source>
            <translation>{} が指定されていますが、パスは {} の工具用に描かれています。その径の工具を指定するか、径を変えて描き直してください</translation>
        </message>
        <message>
            <source>the passes leave {} of the area unswept in {} place; the largest, {}, near ({}, {})</source>
            <translation>パスは領域のうち {} を {} か所で削り残します。最大のものは {} で、({}, {}) 付近です</translation>
        </message>
        <message>
            <source>the passes leave {} of the area unswept in {} places; the largest, {}, near ({}, {})</source>
            <translation>パスは領域のうち {} を {} か所で削り残します。最大のものは {} で、({}, {}) 付近です</translation>
        </message>
        <message>
            <source>the passes were drawn {} mm wide</source>
            <translation>パスが {} mm 幅で描かれています</translation>
        </message>
        <message>
            <source>pocket</source>
            <translation>ポケット</translation>
        </message>
        <message>
            <source>the island {} touches {} at ({}, {}): no end mill passes between them; keep it {} off (the smallest end mill, {}, with what the step leaves on the walls) or make the two one contour</source>
            <translation>島 {0} が ({2}, {3}) で {1} に接しています。間を通るエンドミルはありません。{4} 以上離す(最小のエンドミル {5} と、工程が壁に残す取り代の分)か、二つを一つの輪郭にしてください</translation>
        </message>
        <message>
            <source>the gap between the island {} and {} is {} wide at ({}, {}); the smallest end mill, {}, needs {} there</source>
            <translation>島 {0} と {1} の隙間は ({3}, {4}) で幅 {2} です。最小のエンドミル {5} にはそこで {6} が必要です</translation>
        </message>
        <message>
            <source>{} narrows to {} between ({}, {}) and ({}, {}); the smallest end mill, {}, needs {} there</source>
            <translation>{0} は ({2}, {3}) と ({4}, {5}) の間で幅 {1} まで狭くなっています。最小のエンドミル {6} にはそこで {7} が必要です</translation>
        </message>
        <message>
            <source>{} has an inside arc of radius {} at ({}, {}); the smallest end mill, {}, needs a radius of at least {} there</source>
            <translation>{0} の ({2}, {3}) に半径 {1} の内側円弧があります。最小のエンドミル {4} にはそこで半径 {5} 以上が必要です</translation>
        </message>
        <message>
            <source>the contour's narrowest reach</source>
            <translation>輪郭の最も狭い箇所</translation>
        </message>
        <message>
            <source>{} has an inside arc of radius {} at ({}, {}): the end mills that fit it have flutes shorter than the depth {} (the longest-fluted, {}); {} reaches that depth but needs a radius of {} there, {} more (make the arc larger, or the pocket shallower)</source>
            <translation>{0} の ({2}, {3}) に半径 {1} の内側円弧があります。そこに入るエンドミルは刃長が深さ {4} より短く (刃長の最も長いもので {5})、その深さに届く {6} にはそこで半径 {7} が必要で、{8} 足りません (円弧を大きくするか、ポケットを浅くしてください)</translation>
        </message>
        <message>
            <source>{} narrows to {} between ({}, {}) and ({}, {}): the end mills that pass there have flutes shorter than the depth {} (the longest-fluted, {}); {} reaches that depth but needs it {} wider there (widen it, or make the pocket shallower)</source>
            <translation>{0} は ({2}, {3}) と ({4}, {5}) の間で幅 {1} まで狭くなっています。そこを通るエンドミルは刃長が深さ {6} より短く (刃長の最も長いもので {7})、その深さに届く {8} にはそこをあと {9} 広くする必要があります (そこを広げるか、ポケットを浅くしてください)</translation>
        </message>
        <message>
            <source>the gap between the island {} and {} is {} wide at ({}, {}): the end mills that pass there have flutes shorter than the depth {} (the longest-fluted, {}); {} reaches that depth but needs {} there, {} more (widen the gap, or make the pocket shallower)</source>
            <translation>島 {0} と {1} の隙間は ({3}, {4}) で幅 {2} です。そこを通るエンドミルは刃長が深さ {5} より短く (刃長の最も長いもので {6})、その深さに届く {7} にはそこで {8} が必要で、{9} 足りません (隙間を広げるか、ポケットを浅くしてください)</translation>
        </message>
        <message>
            <source>U {} is not a tool use of face milling; give 1 (roughing layers and a finishing pass) or 9 (roughing only, the finishing allowance left)</source>
            <translation>U {} は正面フライス削りの工具使用ではありません。1 (荒加工層と仕上げパス) か 9 (荒加工のみ、仕上げ代を残す) にしてください</translation>
        </message>
        <message>
            <source>pattern {} is not a face-milling pattern; give 1 (one way, climb: every pass in the same direction) or 2 (zigzag: back and forth)</source>
            <translation>パターン {} は正面フライス削りのパターンではありません。1 (一方向、ダウンカット: 全パス同じ向き) か 2 (ジグザグ: 往復) にしてください</translation>
        </message>
        <message>
            <source>the depth</source>
            <translation>深さ</translation>
        </message>
        <message>
            <source>the depth {} is not less than the stock's height {}: facing takes a layer off the top, it does not mill the whole block away</source>
            <translation>深さ {} が素材の高さ {} 以上です。正面削りは上面の層を取るもので、ブロック全体を削り取るものではありません</translation>
        </message>
        <message>
            <source>the finishing pass</source>
            <translation>仕上げパス</translation>
        </message>
        <message>
            <source>the finishing pass is {}; it must be greater than zero (leave the field empty for the technology data's β2)</source>
            <translation>仕上げパスが {} です。0 より大きくしてください (加工条件の β2 を使うときは空欄のままに)</translation>
        </message>
        <message>
            <source>the finishing pass {}{} is not less than the depth {}: roughing would have nothing to take; give a smaller finishing pass</source>
            <translation>仕上げパス {}{} が深さ {} 以上です。荒加工で削るものがなくなります。仕上げパスを小さくしてください</translation>
        </message>
        <message>
            <source>the angle</source>
            <translation>角度</translation>
        </message>
        <message>
            <source>the angle {} lies beyond ±360°; give the passes' direction from +X, e.g. 0 or 90</source>
            <translation>角度 {} が ±360° を超えています。パスの方向を +X から指定してください (例: 0 または 90)</translation>
        </message>
        <message>
            <source>the step-over {:g} × D must be greater than 0: passes that do not step sideways never cover the face</source>
            <translation>横送り {} × D は 0 より大きくしてください。横にずれないパスでは面全体を削れません</translation>
        </message>
        <message>
            <source>the step-over {:g} × D is less than {:g} × D: the face would take more than a hundred passes a tool diameter</source>
            <translation>横送り {} × D が {} × D 未満です。工具径 1 つ分あたり 100 を超えるパスが必要になります</translation>
        </message>
        <message>
            <source>the step-over {:g} × D is more than {:g} × D: neighbouring passes would overlap by less than a tenth of the diameter, and the inserts' corners and the tool's run-out leave ridges between them</source>
            <translation>横送り {} × D が {} × D を超えています。隣り合うパスの重なりが径の 1/10 未満になり、チップの角と工具の振れでパスの間に筋が残ります</translation>
        </message>
        <message>
            <source>the margin</source>
            <translation>はみ出し量</translation>
        </message>
        <message>
            <source>the margin is {}; it must be 0 (the face is the stock's top) or more (the face reaches beyond the stock's sides): less would leave the top's edges unfaced</source>
            <translation>はみ出し量が {} です。0 (面は素材の上面) 以上 (面は素材の側面の外まで) にしてください。それより小さいと上面の縁が削り残されます</translation>
        </message>
        <message>
            <source>{} is pinned for "face" but is not a face mill or a flat end mill: a face is cut flat by the tool's flat bottom</source>
            <translation>{} が "face" に指定されていますが、正面フライスでもフラットエンドミルでもありません。面は工具の平らな底で平らに削ります</translation>
        </message>
        <message>
            <source>{} is pinned for "face" but is not a face mill or a flat end mill with a corner radius under 0.4 D: a face is cut flat by the tool's flat bottom</source>
            <translation>{} が "face" に指定されていますが、正面フライスでもコーナ半径 0.4 D 未満のフラットエンドミルでもありません。面は工具の平らな底で平らに削ります</translation>
        </message>
        <message>
            <source>{} is pinned for "face" but cuts {} at most, less than the finishing pass {}; give a smaller finishing pass or another tool</source>
            <translation>{} が "face" に指定されていますが、最大切込み {} は仕上げパス {} より小さくなっています。仕上げパスを小さくするか別の工具にしてください</translation>
        </message>
        <message>
            <source>the tool library has no face mill or flat end mill that cuts the finishing pass {} in one cut; add one or give a smaller finishing pass</source>
            <translation>仕上げパス {} を一度で削れる正面フライスもフラットエンドミルも工具ライブラリにありません。追加するか仕上げパスを小さくしてください</translation>
        </message>
        <message>
            <source>largest {} in the library (Ø{}), cutting {} a layer</source>
            <translation>ライブラリで最大の{} (Ø{})、1 層 {} の切込み</translation>
        </message>
        <message>
            <source>{} {} must be 1 to {}</source>
            <translation>{} {} は 1 ～ {} にしてください</translation>
        </message>
        <message>
            <source>the columns</source>
            <translation>列数</translation>
        </message>
        <message>
            <source>the number of holes</source>
            <translation>穴数</translation>
        </message>
        <message>
            <source>the rows</source>
            <translation>行数</translation>
        </message>
        <message>
            <source>{} columns by {} rows are {} holes, more than the {} a unit may have</source>
            <translation>{} 列 × {} 行で {} 穴になり、1 ユニットの上限 {} を超えます</translation>
        </message>
        <message>
            <source>the angle {} must be from -360° to 360°</source>
            <translation>角度 {} は -360° ～ 360° にしてください</translation>
        </message>
        <message>
            <source>{} {} must be greater than zero</source>
            <translation>{} {} は 0 より大きくしてください</translation>
        </message>
        <message>
            <source>the pitch</source>
            <translation>ピッチ</translation>
        </message>
        <message>
            <source>the pitch between rows</source>
            <translation>行間のピッチ</translation>
        </message>
        <message>
            <source>the angular pitch {:g}° must not be 0 and lie within ±360°</source>
            <translation>角度ピッチ {}° は 0 以外で ±360° 以内にしてください</translation>
        </message>
        <message>
            <source>thread "{}" is not one this program taps: ISO metric coarse {}</source>
            <translation>ねじ「{}」はこのプログラムでタップを立てられません。ISO メートル並目: {}</translation>
        </message>
        <message>
            <source>a tapped hole's diameter is its thread's: leave out "diameter"</source>
            <translation>タップ穴の径はねじの径です。"diameter" は省いてください</translation>
        </message>
        <message>
            <source>the diameter</source>
            <translation>径</translation>
        </message>
        <message>
            <source>the diameter {} must be {} to {}</source>
            <translation>径 {} は {} ～ {} にしてください</translation>
        </message>
        <message>
            <source>the depth {} must be greater than zero</source>
            <translation>深さ {} は 0 より大きくしてください</translation>
        </message>
        <message>
            <source>{} {} is not more than the hole's diameter {}: the holes would cut into each other</source>
            <translation>{} {} が穴径 {} 以下です。穴どうしが食い込みます</translation>
        </message>
        <message>
            <source>the distance between neighbouring holes</source>
            <translation>隣り合う穴の間隔</translation>
        </message>
        <message>
            <source>holes {} and {} lie {} apart, not more than the diameter {}: the arc closes on itself; fewer holes or a smaller angular pitch</source>
            <translation>穴 {} と {} の間隔が {} で、径 {} 以下です。円弧が一周して重なります。穴数を減らすか角度ピッチを小さくしてください</translation>
        </message>
        <message>
            <source>hole {} (X {}, Y {}) reaches outside the stock; move the pattern or enlarge the stock</source>
            <translation>穴 {} (X {}, Y {}) が素材の外にはみ出しています。パターンを移動するか素材を大きくしてください</translation>
        </message>
        <message>
            <source>the hole goes down to {} with its drill point (its tools go deeper than the depth {}; docs/holes.md), below the stock's height {}: through holes are not made; make it shallower</source>
            <translation>穴はドリル先端で {} まで達し (工具は深さ {} より深く入ります。docs/holes.md)、素材の高さ {} より下になります。通し穴は作りません。浅くしてください</translation>
        </message>
        <message>
            <source>a {} hole has no step "{}"; its steps are {}</source>
            <translation>{}穴には工程「{}」がありません。工程は {} です</translation>
        </message>
        <message>
            <source>pattern "{}" is not one of {}</source>
            <translation>パターン「{}」は {} のいずれでもありません</translation>
        </message>
        <message>
            <source>hole "{}" is not one of {}</source>
            <translation>穴「{}」は {} のいずれでもありません</translation>
        </message>
        <message>
            <source>T{} ({}) is pinned for "{}" but is not a {}</source>
            <translation>T{} ({}) が「{}」に指定されていますが、{}ではありません</translation>
        </message>
        <message>
            <source>no {} in the tool library; add one</source>
            <translation>工具ライブラリに{}がありません。追加してください</translation>
        </message>
        <message>
            <source>the tap drill of {}</source>
            <translation>{} の下穴ドリル</translation>
        </message>
        <message>
            <source>the hole's</source>
            <translation>穴の</translation>
        </message>
        <message>
            <source>drill of Ø{} ({}) whose flutes reach {}</source>
            <translation>Ø{} のドリル ({})、刃長 {} まで</translation>
        </message>
        <message>
            <source>drill of Ø{}: {}</source>
            <translation>Ø{} のドリル: {}</translation>
        </message>
        <message>
            <source>drill from Ø{} to Ø{} (to {} Ø{}: {} to {} under) whose flutes reach {}</source>
            <translation>Ø{} ～ Ø{} のドリル ({} Ø{} に対して {} ～ {} 小さい)、刃長 {} まで</translation>
        </message>
        <message>
            <source>ream</source>
            <translation>リーマ仕上げ</translation>
        </message>
        <message>
            <source>bore</source>
            <translation>中ぐり</translation>
        </message>
        <message>
            <source>largest drill {} to {} under Ø{} to {}</source>
            <translation>Ø{2} より {0} ～ {1} 小さい最大のドリル ({3} 用)</translation>
        </message>
        <message>
            <source>tap {}x{:g} (type tap, Ø{}, pitch {}) whose flutes reach {}</source>
            <translation>タップ {}x{} (種類 tap、Ø{}、ピッチ {})、刃長 {} まで</translation>
        </message>
        <message>
            <source>tap {}x{:g}</source>
            <translation>タップ {}x{}</translation>
        </message>
        <message>
            <source>{} of Ø{} whose flutes reach {}</source>
            <translation>Ø{1} の{0}、刃長 {2} まで</translation>
        </message>
        <message>
            <source>boring bar (set to the bore)</source>
            <translation>中ぐりバー (穴径に合わせる)</translation>
        </message>
        <message>
            <source>{} of the hole's Ø{}</source>
            <translation>穴径 Ø{1} の{0}</translation>
        </message>
        <message>
            <source>boring tool</source>
            <translation>中ぐりバイト</translation>
        </message>
        <message>
            <source>centre drill spotting Ø{} for the Ø{} drill</source>
            <translation>Ø{1} ドリル用に Ø{0} をもみ付けるセンタードリル</translation>
        </message>
        <message>
            <source>the corner radius</source>
            <translation>コーナ半径</translation>
        </message>
        <message>
            <source>the scallop height</source>
            <translation>カスプ高さ</translation>
        </message>
        <message>
            <source>pocket opening</source>
            <translation>ポケットの開口</translation>
        </message>
        <message>
            <source>roughing layers</source>
            <translation>荒加工の各層</translation>
        </message>
        <message>
            <source>the scallop height is {}; it must be at least {} (a smaller one multiplies the passes of the inclined faces without a finer surface any machine holds)</source>
            <translation>カスプ高さが {} です。{} 以上にしてください (これより小さいと傾斜面のパスが増えるだけで、機械が保てる以上に細かい面にはなりません)</translation>
        </message>
        <message>
            <source>the corner radius {} is larger than half of L2 = {}</source>
            <translation>コーナ半径 {} が L2 = {} の半分より大きくなっています</translation>
        </message>
        <message>
            <source>{} = {} is outside 0° to under 60° (measured from the vertical)</source>
            <translation>{} = {} が 0° 以上 60° 未満の範囲外です (垂直から測ります)</translation>
        </message>
        <message>
            <source>the inclined walls leave a floor {} wide along L1; it must be wider than 2 × r1 = {} (short by {}): reduce the angles or the depth, or lengthen L1</source>
            <translation>傾斜壁によって L1 方向の底の幅が {} になります。2 × r1 = {} より広くなければなりません ({} 不足)。角度か深さを小さくするか、L1 を長くしてください</translation>
        </message>
        <message>
            <source>the scallop height is {}; it must be greater than zero (usual 0.01 mm)</source>
            <translation>カスプ高さが {} です。0 より大きくしてください (通常 0.01 mm)</translation>
        </message>
        <message>
            <source>tool-use code U = {} is not allowed for M2D; use 1 (rough and finish) or 9 (rough only)</source>
            <translation>工具使用コード U = {} は M2D では使えません。1 (荒加工と仕上げ) か 9 (荒加工のみ) にしてください</translation>
        </message>
        <message>
            <source>the coordinate X of {}</source>
            <translation>{} の X 座標</translation>
        </message>
        <message>
            <source>the coordinate Y of {}</source>
            <translation>{} の Y 座標</translation>
        </message>
        <message>
            <source>the cornerRadius</source>
            <translation>コーナ半径</translation>
        </message>
        <message>
            <source>the taper</source>
            <translation>テーパ</translation>
        </message>
        <message>
            <source>an array of 4 points [x, y]</source>
            <translation>4 つの点 [x, y] の配列</translation>
        </message>
        <message>
            <source>the final wall allowance α3 = {} must be smaller than the roughing wall allowance α2 = {}</source>
            <translation>壁の最終仕上げ代 α3 = {} は荒加工の壁仕上げ代 α2 = {} より小さくしてください</translation>
        </message>
        <message>
            <source>P{} and P{} are the same point ({}, {}); the outline needs four distinct corners</source>
            <translation>P{} と P{} が同じ点 ({}, {}) です。輪郭には異なる 4 つの角が必要です</translation>
        </message>
        <message>
            <source>the outline crosses itself; enter the corners P1..P4 in order around the pocket</source>
            <translation>外形が自分自身と交差しています。角 P1..P4 をポケットの周りに順に入力してください</translation>
        </message>
        <message>
            <source>the outline is not convex (a corner points inward or three corners are in line)</source>
            <translation>外形が凸ではありません (内向きの角があるか、3 つの角が一直線上にあります)</translation>
        </message>
        <message>
            <source>the corner radius {} is larger than half the shortest side ({} long)</source>
            <translation>コーナ半径 {} が最短辺 (長さ {}) の半分より大きくなっています</translation>
        </message>
        <message>
            <source>the corner radius {} does not fit: the largest circle inside the outline has radius {}</source>
            <translation>コーナ半径 {} が入りません。外形に内接する最大の円の半径は {} です</translation>
        </message>
        <message>
            <source>the taper {} per side is outside 0° to 30°</source>
            <translation>片側テーパ {} が 0° ～ 30° の範囲外です</translation>
        </message>
        <message>
            <source>with a taper of {} per side the walls meet at depth {}, above the floor</source>
            <translation>片側テーパ {} では壁どうしが底より上の深さ {} で交わります</translation>
        </message>
        <message>
            <source>an array of contour names</source>
            <translation>輪郭名の配列</translation>
        </message>
        <message>
            <source>a contour name</source>
            <translation>輪郭名</translation>
        </message>
        <message>
            <source>outline</source>
            <translation>外形</translation>
        </message>
        <message>
            <source>{} islands; a {} may have at most {} (the checks compare every two of them)</source>
            <translation>島が {} 個あります。{}の島は最大 {} 個です（検査ですべての 2 つの組を比べます）</translation>
        </message>
        <message>
            <source>the {}'s outline {} and its islands have {} lines and arcs; at most {} are taken (simplify the contours, or join short lines into arcs)</source>
            <translation>{}の外形 {} と島の線・円弧は {} 本です。最大 {} 本までです（輪郭を簡単にするか、短い線を円弧にまとめてください）</translation>
        </message>
        <message>
            <source>island</source>
            <translation>島</translation>
        </message>
        <message>
            <source>tool-use code U = {} is not defined (codes 2 to 5 are reserved); use 1, 6, 7, 8 or 9</source>
            <translation>工具使用コード U = {} は定義されていません (2 ～ 5 は予約)。1、6、7、8、9 のいずれかにしてください</translation>
        </message>
        <message>
            <source>tool-use code U = {} does not exist; use 1, 6, 7, 8 or 9</source>
            <translation>工具使用コード U = {} はありません。1、6、7、8、9 のいずれかにしてください</translation>
        </message>
        <message>
            <source>finishing code F = {} does not exist; use 1, 2 or 3</source>
            <translation>仕上げコード F = {} はありません。1、2、3 のいずれかにしてください</translation>
        </message>
        <message>
            <source>pilot-hole code H = {} does not exist; use 0 (drill a pilot hole) or 9 (none)</source>
            <translation>下穴コード H = {} はありません。0 (下穴をあける) か 9 (なし) にしてください</translation>
        </message>
        <message>
            <source>the corner radius is {}; it cannot be negative</source>
            <translation>コーナ半径が {} です。負の値にはできません</translation>
        </message>
        <message>
            <source>U {} is not offered for contour pockets; use 1 (all steps), 6 (no wall finishing), 8 (walls only) or 9 (roughing only)</source>
            <translation>U {} は輪郭ポケットでは使えません。1 (全工程)、6 (壁仕上げなし)、8 (壁のみ)、9 (荒加工のみ) のいずれかにしてください</translation>
        </message>
        <message>
            <source>largest {} ({}) whose radius {} fits the corner radius {} of the {}</source>
            <translation>{4}用の、半径 {2} がコーナー半径 {3} に入る最大の{0} ({1})</translation>
        </message>
        <message>
            <source>largest {} ({}) of diameter at most half the pocket's inscribed width {} of the {}</source>
            <translation>{3}用の、直径がポケットの内接幅 {2} の半分以下で最大の{0} ({1})</translation>
        </message>
        <message>
            <source>largest {} ({}) of diameter at most half the pocket's inscribed width {}</source>
            <translation>直径がポケットの内接幅 {2} の半分以下で最大の{0} ({1})</translation>
        </message>
        <message>
            <source>largest {} ({}) of diameter at most half the pocket's inscribed width {}; it cuts at its centre and ramps in (no pilot hole)</source>
            <translation>直径がポケットの内接幅 {2} の半分以下で最大の{0} ({1})。中心刃があり、斜めに切り込みます (下穴なし)</translation>
        </message>
        <message>
            <source>largest {} ({}) of diameter at most half the pocket's inscribed width {}; enters the {} pilot hole</source>
            <translation>直径がポケットの内接幅 {2} の半分以下で最大の{0} ({1})。{3} の下穴から入ります</translation>
        </message>
        <message>
            <source>largest {} ({}) of diameter at most half the pocket's inscribed width {}; its flutes ({}) are shorter than the depth {}, as are those of every end mill that fits: it cuts one layer at a time</source>
            <translation>直径がポケットの内接幅 {2} の半分以下で最大の{0} ({1})。刃長 ({3}) が深さ {4} に届きませんが、入るエンドミルはどれも同じです: 1 層ずつ削ります</translation>
        </message>
        <message>
            <source>largest {} ({}) of diameter at most half the pocket's inscribed width {}; its flutes ({}) are shorter than the depth {}, as are those of every end mill that fits: it cuts one layer at a time; it cuts at its centre and ramps in (no pilot hole)</source>
            <translation>直径がポケットの内接幅 {2} の半分以下で最大の{0} ({1})。刃長 ({3}) が深さ {4} に届きませんが、入るエンドミルはどれも同じです: 1 層ずつ削ります。中心刃があり、斜めに切り込みます (下穴なし)</translation>
        </message>
        <message>
            <source>largest {} ({}) of diameter at most half the pocket's inscribed width {}; its flutes ({}) are shorter than the depth {}, as are those of every end mill that fits: it cuts one layer at a time; enters the {} pilot hole</source>
            <translation>直径がポケットの内接幅 {2} の半分以下で最大の{0} ({1})。刃長 ({3}) が深さ {4} に届きませんが、入るエンドミルはどれも同じです: 1 層ずつ削ります。{5} の下穴から入ります</translation>
        </message>
        <message>
            <source>largest {} ({}) whose radius {} fits the corner radius {}</source>
            <translation>半径 {2} がコーナー半径 {3} に入る最大の{0} ({1})</translation>
        </message>
        <message>
            <source>largest {} ({}) whose radius {} fits the corner radius {}; it cuts at its centre and ramps in (no pilot hole)</source>
            <translation>半径 {2} がコーナー半径 {3} に入る最大の{0} ({1})。中心刃があり、斜めに切り込みます (下穴なし)</translation>
        </message>
        <message>
            <source>largest {} ({}) whose radius {} fits the corner radius {}; enters the {} pilot hole</source>
            <translation>半径 {2} がコーナー半径 {3} に入る最大の{0} ({1})。{4} の下穴から入ります</translation>
        </message>
        <message>
            <source>largest {} ({}) whose radius {} fits the corner radius {}; its flutes ({}) are shorter than the depth {}, as are those of every end mill that fits: it cuts one layer at a time</source>
            <translation>半径 {2} がコーナー半径 {3} に入る最大の{0} ({1})。刃長 ({4}) が深さ {5} に届きませんが、入るエンドミルはどれも同じです: 1 層ずつ削ります</translation>
        </message>
        <message>
            <source>largest {} ({}) whose radius {} fits the corner radius {}; its flutes ({}) are shorter than the depth {}, as are those of every end mill that fits: it cuts one layer at a time; it cuts at its centre and ramps in (no pilot hole)</source>
            <translation>半径 {2} がコーナー半径 {3} に入る最大の{0} ({1})。刃長 ({4}) が深さ {5} に届きませんが、入るエンドミルはどれも同じです: 1 層ずつ削ります。中心刃があり、斜めに切り込みます (下穴なし)</translation>
        </message>
        <message>
            <source>largest {} ({}) whose radius {} fits the corner radius {}; its flutes ({}) are shorter than the depth {}, as are those of every end mill that fits: it cuts one layer at a time; enters the {} pilot hole</source>
            <translation>半径 {2} がコーナー半径 {3} に入る最大の{0} ({1})。刃長 ({4}) が深さ {5} に届きませんが、入るエンドミルはどれも同じです: 1 層ずつ削ります。{6} の下穴から入ります</translation>
        </message>
        <message>
            <source>taper end mill of the wall's taper {:g} deg per side (tip {}) whose tip radius {} fits the corner radius {} at the floor</source>
            <translation>側壁のテーパ片側 {0} 度のテーパエンドミル (先端 {1})。先端半径 {2} が底のコーナー半径 {3} に入ります</translation>
        </message>
        <message>
            <source>largest ball end mill ({}) of radius at most 6 mm and half the inclined face's length {}</source>
            <translation>半径が 6 mm 以下かつ傾斜面の長さ {1} の半分以下で最大のボールエンドミル ({0})</translation>
        </message>
        <message>
            <source>{}: pinned tool T{} is not in the tool library</source>
            <translation>{}: 指定された工具 T{} が工具ライブラリにありません</translation>
        </message>
        <message>
            <source>{}: pinned tool T{} ({}) does not fit: {}</source>
            <translation>{}: 指定された工具 T{} ({}) は合いません: {}</translation>
        </message>
        <message>
            <source>pinned by the operator</source>
            <translation>オペレータが指定</translation>
        </message>
        <message>
            <source>smallest drill ({}) not smaller than the {} end mill that plunges into it</source>
            <translation>{1} のエンドミルがプランジする穴の、それより小さくない最小のドリル ({0})</translation>
        </message>
        <message>
            <source>shape {} is not defined: 1 round (boss or bore), 2 rectangular (block or pocket)</source>
            <translation>形状 {} は定義されていません: 1 円形 (ボスまたは穴)、2 矩形 (ブロックまたはポケット)</translation>
        </message>
        <message>
            <source>where {} is not defined: 1 touched from outside (boss, block), 2 from inside (bore, pocket)</source>
            <translation>測定側 {} は定義されていません: 1 外側から (ボス、ブロック)、2 内側から (穴、ポケット)</translation>
        </message>
        <message>
            <source>the X of {}</source>
            <translation>{} の X</translation>
        </message>
        <message>
            <source>the Y of {}</source>
            <translation>{} の Y</translation>
        </message>
        <message>
            <source>point {}: its {} is missing</source>
            <translation>点 {}: {} がありません</translation>
        </message>
        <message>
            <source>point {}: say which side it touches: 1 -X, 2 +X, 3 -Y, 4 +Y</source>
            <translation>点 {}: どの面に触れるか指定してください: 1 -X、2 +X、3 -Y、4 +Y</translation>
        </message>
        <message>
            <source>point 1 is the measuring origin: it is at 0, 0 and the others are measured from it</source>
            <translation>点 1 は測定原点です。0, 0 にあり、他の点はそこから測ります</translation>
        </message>
        <message>
            <source>the machine Z of the top face</source>
            <translation>上面の機械座標 Z</translation>
        </message>
        <message>
            <source>{} must be above 0 and at most {:g} mm, not {:g}</source>
            <translation>{} は 0 より大きく {} mm 以下にしてください ({} ではなく)</translation>
        </message>
        <message>
            <source>the nominal width along X</source>
            <translation>X 方向の呼び幅</translation>
        </message>
        <message>
            <source>the nominal diameter</source>
            <translation>呼び径</translation>
        </message>
        <message>
            <source>the nominal length along Y</source>
            <translation>Y 方向の呼び長さ</translation>
        </message>
        <message>
            <source>the depth of the side touches</source>
            <translation>側面測定の深さ</translation>
        </message>
        <message>
            <source>the clearance</source>
            <translation>逃げ</translation>
        </message>
        <message>
            <source>the search distance</source>
            <translation>探索距離</translation>
        </message>
        <message>
            <source>the probing feed must be above 0 and at most 5000 mm/min, not {:g}</source>
            <translation>測定送りは 0 より大きく 5000 mm/min 以下にしてください ({} ではなく)</translation>
        </message>
        <message>
            <source>the tolerance must lie between 0.001 and 1 mm, not {:g}</source>
            <translation>公差は 0.001 ～ 1 mm にしてください ({} ではなく)</translation>
        </message>
        <message>
            <source>T{} is not a probe in the tool library</source>
            <translation>T{} は工具ライブラリのタッチプローブではありません</translation>
        </message>
        <message>
            <source>the tool library has no probe, or several: add one of type "probe" or say which (T)</source>
            <translation>工具ライブラリにタッチプローブがないか、複数あります。種類 "probe" を 1 つ追加するか、どれを使うか指定してください (T)</translation>
        </message>
        <message>
            <source>point {} coincides with point {}: touch the outline elsewhere</source>
            <translation>点 {} が点 {} と一致しています。外形の別の場所をタッチしてください</translation>
        </message>
        <message>
            <source>point {} is {} off the fitted {} (tolerance {}): touch it again, or check the shape and the order of the points</source>
            <translation>点 {0} が当てはめた{2}から {1} 外れています (許容値 {3})。タッチし直すか、形状と点の順序を確認してください</translation>
        </message>
        <message>
            <source>a round workpiece needs at least 3 touch points, {} given</source>
            <translation>円形のワークには 3 点以上のタッチ点が必要ですが、{} 点です</translation>
        </message>
        <message>
            <source>point {} lies on the line of points 1 to {} (within {}): a circle needs touches spread around it</source>
            <translation>点 {0} が点 1 ～ {1} の直線上にあります ({2} 以内)。円には周囲に散らばったタッチが必要です</translation>
        </message>
        <message>
            <source>circle</source>
            <translation>円</translation>
        </message>
        <message>
            <source>the touches lie on a circle of radius {}, no larger than the stylus ball's radius {}: is the workpiece a bore rather than a boss?</source>
            <translation>タッチ点は半径 {} の円上にあり、スタイラス球の半径 {} より大きくありません。ワークはボスではなく穴ではありませんか?</translation>
        </message>
        <message>
            <source>point {}: the side it touches is not given</source>
            <translation>点 {}: タッチする面が指定されていません</translation>
        </message>
        <message>
            <source>a rectangular workpiece needs a touch on every side: none on {}</source>
            <translation>長方形のワークには各面にタッチが必要ですが、{} にありません</translation>
        </message>
        <message>
            <source>the points on -X and +X are swapped: the +X side (point {}) lies at or left of the -X side (point {})</source>
            <translation>-X と +X の点が入れ替わっています。+X 面 (点 {}) が -X 面 (点 {}) と同じ位置かその左にあります</translation>
        </message>
        <message>
            <source>the points on -Y and +Y are swapped: the +Y side (point {}) lies at or below the -Y side (point {})</source>
            <translation>-Y と +Y の点が入れ替わっています。+Y 面 (点 {}) が -Y 面 (点 {}) と同じ位置かその下にあります</translation>
        </message>
        <message>
            <source>rectangle</source>
            <translation>長方形</translation>
        </message>
        <message>
            <source>the touches span {} x {}, no more than the stylus ball: is the workpiece a pocket rather than a block?</source>
            <translation>タッチ点の範囲は {} x {} で、スタイラス球より大きくありません。ワークはブロックではなくポケットではありませんか?</translation>
        </message>
        <message>
            <source>an array of 1 to 8 points [x, y], the first [0, 0]</source>
            <translation>1 ～ 8 個の点 [x, y] の配列 (最初は [0, 0])</translation>
        </message>
        <message>
            <source>a point [x, y] or null</source>
            <translation>点 [x, y] または null</translation>
        </message>
        <message>
            <source>an array of up to 8 side codes (1 -X, 2 +X, 3 -Y, 4 +Y)</source>
            <translation>最大 8 個の面コードの配列 (1 -X、2 +X、3 -Y、4 +Y)</translation>
        </message>
        <message>
            <source>No probe in the tool library (type "probe"): the ball radius is unknown</source>
            <translation>工具ライブラリにプローブ (種類 "probe") がありません: 球の半径がわかりません</translation>
        </message>
        <message>
            <source>{} of at least {} touches entered: the probing cycle the export writes makes them on the machine</source>
            <translation>測定点は {} 点入力済み (最低 {} 点): 出力する測定サイクルが機械上で測定します</translation>
        </message>
        <message>
            <source>Bore: diameter {}</source>
            <translation>穴: 直径 {}</translation>
        </message>
        <message>
            <source>Boss: diameter {}</source>
            <translation>ボス: 直径 {}</translation>
        </message>
        <message>
            <source>(not measured: touch one side twice)</source>
            <translation>(未測定: 一つの面を 2 回測定してください)</translation>
        </message>
        <message>
            <source>Pocket: {} x {}, turned {}</source>
            <translation>ポケット: {} x {}、回転 {}</translation>
        </message>
        <message>
            <source>Block: {} x {}, turned {}</source>
            <translation>ブロック: {} x {}、回転 {}</translation>
        </message>
        <message>
            <source>Centre from P1: X {} Y {}</source>
            <translation>P1 からの中心: X {} Y {}</translation>
        </message>
        <message>
            <source>Work offset to set: X {} Y {} Z {}</source>
            <translation>設定するワーク座標: X {} Y {} Z {}</translation>
        </message>
        <message>
            <source>Work offset to set: X {} Y {}</source>
            <translation>設定するワーク座標: X {} Y {}</translation>
        </message>
        <message>
            <source>the {} reaches outside the stock; move it or enlarge the stock</source>
            <translation>{}が素材の外にはみ出しています。移動するか素材を大きくしてください</translation>
        </message>
        <message>
            <source>name the contour of the pocket's {} (a CONTOUR of the job's figure elements)</source>
            <translation>ポケットの{}の輪郭を指定してください (ジョブの図形要素の CONTOUR)</translation>
        </message>
        <message>
            <source>{} is not a contour of the job's figure elements, which define no contour</source>
            <translation>{} はジョブの図形要素の輪郭ではありません (輪郭が一つも定義されていません)</translation>
        </message>
        <message>
            <source>{} is not a contour of the job's figure elements (its contours: {})</source>
            <translation>{} はジョブの図形要素の輪郭ではありません (輪郭: {})</translation>
        </message>
        <message>
            <source>{} is an open contour; an {}'s {} must be closed (a contour without a start and end point)</source>
            <translation>{0} は開いた輪郭です。{1}の{2}は閉じていなければなりません (始点と終点のない輪郭)</translation>
        </message>
        <message>
            <source>{} is an open contour; a {}'s {} must be closed (a contour without a start and end point)</source>
            <translation>{0} は開いた輪郭です。{1}の{2}は閉じていなければなりません (始点と終点のない輪郭)</translation>
        </message>
        <message>
            <source>{} crosses itself; check the order of its elements and the side chosen at each junction</source>
            <translation>{} が自分自身と交差しています。要素の順序と各接続点で選んだ側を確認してください</translation>
        </message>
        <message>
            <source>the island {} reaches outside the {}'s outline {}</source>
            <translation>島 {0} が{1}の外形 {2} の外にはみ出しています</translation>
        </message>
        <message>
            <source>the islands {} and {} overlap; make them one contour</source>
            <translation>島 {} と {} が重なっています。一つの輪郭にしてください</translation>
        </message>
        <message>
            <source>{} has a sharp inside corner at ({}, {}): an end mill cannot cut it and leaves its own radius there; round the corner (ROUND) in the contour</source>
            <translation>{} の ({}, {}) に鋭い内角があります。エンドミルでは削れず、工具の半径が残ります。輪郭でその角を丸めてください (ROUND)</translation>
        </message>
        <message>
            <source>the width</source>
            <translation>幅</translation>
        </message>
        <message>
            <source>the width W</source>
            <translation>幅 W</translation>
        </message>
        <message>
            <source>the contour's smallest inside radius on the tool's side</source>
            <translation>工具側の輪郭の最小内側半径</translation>
        </message>
        <message>
            <source>pinned tool T{} ({}) does not fit: {}</source>
            <translation>指定された工具 T{} ({}) は使えません: {}</translation>
        </message>
        <message>
            <source>no end mill that fits {} reaches the depth {} with its flutes for the finishing at full depth (F 1): the longest, {}, has flutes of {}; finish in several incisions (F 2)</source>
            <translation>{0} に入るエンドミルで、全深さ一度の仕上げ(F 1)のために深さ {1} まで刃長が届くものはありません。最長の {2} の刃長は {3} です。複数回の切込みで仕上げてください(F 2)</translation>
        </message>
        <message>
            <source>{} leaves no room near ({}, {}): even the smallest end mill that fits its arcs, {}, would cut {} into it there; widen the contour there</source>
            <translation>{0} は ({1}, {2}) 付近に余地がありません。円弧に入る最小のエンドミル {3} でも、そこで {4} 食い込みます。そこで輪郭の幅を広げてください</translation>
        </message>
        <message>
            <source>{} along {}</source>
            <translation>{} ({} に沿って)</translation>
        </message>
        <message>
            <source>largest flat end mill ({}) whose radius {} fits the contour's smallest inside radius {} and whose passes keep off the contour; its flutes ({}) are shorter than T: it cuts in layers</source>
            <translation>半径 {1} が輪郭の最小内側半径 {2} に入り、パスが輪郭から離れる最大のフラットエンドミル ({0})。刃長 ({3}) が T より短いので層に分けて削ります</translation>
        </message>
        <message>
            <source>largest flat end mill ({}) whose radius {} fits the contour's smallest inside radius {} and whose passes keep off the contour</source>
            <translation>半径 {1} が輪郭の最小内側半径 {2} に入り、パスが輪郭から離れる最大のフラットエンドミル ({0})</translation>
        </message>
        <message>
            <source>largest flat end mill ({}) and whose passes keep off the contour; its flutes ({}) are shorter than T: it cuts in layers</source>
            <translation>パスが輪郭から離れる最大のフラットエンドミル ({0})。刃長 ({1}) が T より短いので層に分けて削ります</translation>
        </message>
        <message>
            <source>largest flat end mill ({}) and whose passes keep off the contour</source>
            <translation>パスが輪郭から離れる最大のフラットエンドミル ({})</translation>
        </message>
        <message>
            <source>the arc of {} at ({}, {}) curves round the tool's side with radius {}: the smallest end mill, {}, is {} too large for it (an arc of radius {} or more would let it fit)</source>
            <translation>{0} の ({1}, {2}) の円弧は工具側に半径 {3} で曲がっています。最小のエンドミル {4} はそれより {5} 大きすぎます(半径 {6} 以上の円弧なら入ります)</translation>
        </message>
        <message>
            <source>name the contour the side milling follows (a CONTOUR of the job's figure elements, open or closed)</source>
            <translation>側面削りがたどる輪郭を指定してください (ジョブの図形要素の CONTOUR、開いていても閉じていてもよい)</translation>
        </message>
        <message>
            <source>{} {} is not a code of side milling; use {}</source>
            <translation>{} {} は側面削りのコードではありません。{} にしてください</translation>
        </message>
        <message>
            <source>the width W is {}; roughing leaves α2 = {} on the wall, so W must be larger than that</source>
            <translation>幅 W が {} です。荒加工は壁に α2 = {} を残すので、W はそれより大きくしてください</translation>
        </message>
        <message>
            <source>{}: {}</source>
            <translation>{}: {}</translation>
        </message>
        <message>
            <source>{} does not fit where {} narrows near ({}, {}): the tool would cut into the contour there; pin a smaller end mill or widen the channel</source>
            <translation>{0} は {1} が狭くなる ({2}, {3}) 付近に入りません。そこで輪郭に食い込みます。小さいエンドミルを指定するか溝を広げてください</translation>
        </message>
        <message>
            <source>curve 1</source>
            <translation>曲線 1</translation>
        </message>
        <message>
            <source>curve 2</source>
            <translation>曲線 2</translation>
        </message>
        <message>
            <source>the figure has no contour {}; its open contours: {}</source>
            <translation>図形に輪郭 {0} はありません。開いた輪郭: {1}</translation>
        </message>
        <message>
            <source>contour {} is closed; a projection runs from one end to the other</source>
            <translation>輪郭 {0} は閉じています。投影は一端から他端へ向かう輪郭です</translation>
        </message>
        <message>
            <source>{} has one point; give two or more [x, y, z]</source>
            <translation>{} の点が 1 つだけです。2 点以上の [x, y, z] を入力してください</translation>
        </message>
        <message>
            <source>{} has neither points [x, y, z] nor two projections (XY, YZ or ZX)</source>
            <translation>{} には点 [x, y, z] も 2 つの投影 (XY、YZ または ZX) もありません</translation>
        </message>
        <message>
            <source>{}: projection {} is in plane "{}"; give XY, YZ or ZX</source>
            <translation>{}: 投影 {} の平面が "{}" です。XY、YZ または ZX にしてください</translation>
        </message>
        <message>
            <source>projection {}: {}</source>
            <translation>投影 {}: {}</translation>
        </message>
        <message>
            <source>{} "{}" does not read: give points "x, y, z; x, y, z" or two projections "XY: a, b; a, b / ZX: a, b; a, b"</source>
            <translation>{} "{}" が読めません。点 "x, y, z; x, y, z" か 2 つの投影 "XY: a, b; a, b / ZX: a, b; a, b" を入力してください</translation>
        </message>
        <message>
            <source>the surface needs at least 2 paths of 2 points or more</source>
            <translation>曲面には 2 点以上のパスが少なくとも 2 本必要です</translation>
        </message>
        <message>
            <source>path {} has {} points; every path has as many as the first ({})</source>
            <translation>パス {} の点は {} 個です。どのパスも最初のパスと同じ数 ({}) の点が必要です</translation>
        </message>
        <message>
            <source>N {} must be 1 or more: the roughing surface needs pieces</source>
            <translation>N {} は 1 以上にしてください。荒加工の曲面には分割が必要です</translation>
        </message>
        <message>
            <source>give M (the finishing surface's pieces) or the step along the curves that implies it</source>
            <translation>M (仕上げの曲面の分割数) か、それを決める曲線に沿ったピッチを入力してください</translation>
        </message>
        <message>
            <source>N {} is not less than M {}: the finishing surface must be divided more finely than the roughing surface (N &lt; M)</source>
            <translation>N {} が M {} より小さくありません: 仕上げの曲面は荒加工の曲面より細かく分けてください (N &lt; M)</translation>
        </message>
        <message>
            <source>the surface rises to Z {} above the stock top (Z 0); the surface is cut into the stock from above</source>
            <translation>曲面が素材上面 (Z 0) より上の Z {} まで上がっています。曲面は素材を上から削って作ります</translation>
        </message>
        <message>
            <source>the surface goes down to Z {}, through the stock's bottom (height {})</source>
            <translation>曲面が Z {} まで下がり、素材の底 (高さ {}) を突き抜けています</translation>
        </message>
        <message>
            <source>the scallop height {} must be greater than 0</source>
            <translation>カスプ高さ {} は 0 より大きくしてください</translation>
        </message>
        <message>
            <source>the allowance {} must be 0 or more</source>
            <translation>仕上げ代 {} は 0 以上にしてください</translation>
        </message>
        <message>
            <source>the boundary "{}" does not read: give paths of points "x, y, z; x, y, z" separated by "/"</source>
            <translation>境界 "{}" が読めません。点 "x, y, z; x, y, z" のパスを "/" で区切って入力してください</translation>
        </message>
        <message>
            <source>the boundary makes no surface: give two or more paths with the same number of points</source>
            <translation>境界が曲面になりません。同じ点数のパスを 2 本以上入力してください</translation>
        </message>
        <message>
            <source>the boundary surface never meets the surface: no path would stop at it; move it onto the surface or leave it out</source>
            <translation>境界の曲面が加工する曲面とどこでも交わらず、そこで止まるパスがありません。曲面と交わる位置に移すか、境界をなくしてください</translation>
        </message>
        <message>
            <source>{} is pinned for "surface" but is not a ball end mill</source>
            <translation>{} が "surface" に指定されていますが、ボールエンドミルではありません</translation>
        </message>
        <message>
            <source>{} is pinned for "surface" but its radius {} is not less than the surface's smallest concave radius {} ({}); {} would fit</source>
            <translation>{} が "surface" に指定されていますが、半径 {} が曲面の最小凹半径 {} ({}) より小さくありません。{} なら入ります</translation>
        </message>
        <message>
            <source>{} is pinned for "surface" but its radius {} is not less than the surface's smallest concave radius {} ({}), and the library has no smaller ball end mill</source>
            <translation>{} が "surface" に指定されていますが、半径 {} が曲面の最小凹半径 {} ({}) より小さくなく、ライブラリにそれより小さいボールエンドミルもありません</translation>
        </message>
        <message>
            <source>the tool library has no ball end mill; add one</source>
            <translation>工具ライブラリにボールエンドミルがありません。追加してください</translation>
        </message>
        <message>
            <source>the tool library has no ball end mill with a radius less than the surface's smallest concave radius {} ({}); add a smaller one</source>
            <translation>工具ライブラリに、半径が曲面の最小凹半径 {} ({}) より小さいボールエンドミルがありません。小さいものを追加してください</translation>
        </message>
        <message>
            <source>largest ball end mill (Ø{:g} mm); the surface has no concave bend</source>
            <translation>最大のボールエンドミル (Ø{} mm)。曲面に凹の曲がりはありません</translation>
        </message>
        <message>
            <source>largest ball end mill (Ø{:g} mm) under the smallest concave radius {} ({})</source>
            <translation>最小凹半径 {1} ({2}) より小さい最大のボールエンドミル (Ø{0} mm)</translation>
        </message>
        <message>
            <source>a TURN unit</source>
            <translation>TURN ユニット</translation>
        </message>
        <message>
            <source>the start point</source>
            <translation>始点</translation>
        </message>
        <message>
            <source>an array of profile rows</source>
            <translation>形状の行の配列</translation>
        </message>
        <message>
            <source>a profile row</source>
            <translation>形状の行</translation>
        </message>
        <message>
            <source>a thread</source>
            <translation>ねじ</translation>
        </message>
        <message>
            <source>an array of grinding-allowance rows</source>
            <translation>研削代の行の配列</translation>
        </message>
        <message>
            <source>a grinding-allowance row</source>
            <translation>研削代の行</translation>
        </message>
        <message>
            <source>an array of step names</source>
            <translation>工程名の配列</translation>
        </message>
        <message>
            <source>a step name</source>
            <translation>工程名</translation>
        </message>
        <message>
            <source>the {} has {} rows; a turned profile has at most {} (split the part into several units)</source>
            <translation>{}が {} 行あります。旋削形状は最大 {} 行です (部品を複数のユニットに分けてください)</translation>
        </message>
        <message>
            <source>"{}" is not a turning step; steps are {}</source>
            <translation>「{}」は旋削の工程ではありません。工程は {} です</translation>
        </message>
        <message>
            <source>{} is on an inner profile: internal threads are not cut yet (only external ones)</source>
            <translation>{} は内径形状上にあります。内ねじはまだ切れません (外ねじのみ)</translation>
        </message>
        <message>
            <source>{} is an arc: a thread is cut on a straight row along the axis</source>
            <translation>{} は円弧です。ねじは軸に沿った直線の行に切ります</translation>
        </message>
        <message>
            <source>{} is not a cylinder cut toward the chuck (a taper or a face): a thread is cut on a straight row along the axis, from the front back</source>
            <translation>{} はチャック側へ削る円筒ではありません (テーパか端面)。ねじは軸に沿った直線の行に、前から奥へ切ります</translation>
        </message>
        <message>
            <source>{} has a grinding allowance: a thread is not ground</source>
            <translation>{} に研削代があります。ねじは研削しません</translation>
        </message>
        <message>
            <source>a pitch of {} is out of range: {} to {}</source>
            <translation>ピッチ {} が範囲外です: {} ～ {}</translation>
        </message>
        <message>
            <source>a thread {} deep does not fit Ø{} with pitch {}: at most {} (the sharp V's height, and a core of half the diameter)</source>
            <translation>深さ {0} のねじはピッチ {2} で Ø{1} に入りません。最大 {3} です (とがった V の高さと、径の半分の芯)</translation>
        </message>
        <message>
            <source>no external threading insert of the tool library cuts a pitch of {}</source>
            <translation>ピッチ {} を切れる外ねじ用ねじ切りチップが工具ライブラリにありません</translation>
        </message>
        <message>
            <source>the profile reaches Ø{}, more than the bar's Ø{}</source>
            <translation>形状が Ø{} に達し、棒材の Ø{} を超えています</translation>
        </message>
        <message>
            <source>the profile with its grinding allowances reaches Ø{}, more than the bar's Ø{}</source>
            <translation>研削代を含めた形状が Ø{} に達し、棒材の Ø{} を超えています</translation>
        </message>
        <message>
            <source>the profile reaches Z{}, beyond the bar's face stock (Z{})</source>
            <translation>形状が Z{} に達し、棒材の端面取り代 (Z{}) を超えています</translation>
        </message>
        <message>
            <source>the profile reaches Z{}, beyond the bar's end (Z{})</source>
            <translation>形状が Z{} に達し、棒材の端 (Z{}) を超えています</translation>
        </message>
        <message>
            <source>pinned</source>
            <translation>オペレータが指定</translation>
        </message>
        <message>
            <source>the bar has face stock but the tool library has no outside turning insert to face it</source>
            <translation>棒材に端面の取り代がありますが、工具ライブラリに端面を削る外径用の旋削チップがありません</translation>
        </message>
        <message>
            <source>the outside roughing insert faces the bar (largest nose radius)</source>
            <translation>外径荒加工用チップで端面を削ります (ノーズ半径最大)</translation>
        </message>
        <message>
            <source>the bore is too narrow for the boring bar (it enters {}; the bore less its allowance leaves {}) and no drill of the library makes it to size</source>
            <translation>穴が中ぐりバイトには狭すぎ (バイトは {} から入り、穴径から中ぐり代を除くと {} です)、その寸法にするドリルがライブラリにありません</translation>
        </message>
        <message>
            <source>the bore needs a drilled hole of {} to {} (the boring bar enters {}), and the tool library has no drill in that range</source>
            <translation>中ぐりには {} ～ {} の下穴が必要ですが (中ぐりバイトは {} から入ります)、工具ライブラリにその範囲のドリルがありません</translation>
        </message>
        <message>
            <source>largest drill within the bore less its allowance ({}), not smaller than the boring bar's bore {}</source>
            <translation>中ぐり代を除いた穴径 ({}) 以内で、中ぐりバイトの必要穴径 {} 以上の最大のドリル</translation>
        </message>
        <message>
            <source>smallest centre drill</source>
            <translation>最小のセンタドリル</translation>
        </message>
        <message>
            <source>the tool library has no inside (boring) turning insert</source>
            <translation>工具ライブラリに内径用 (中ぐり) の旋削チップがありません</translation>
        </message>
        <message>
            <source>the tool library has no outside turning insert</source>
            <translation>工具ライブラリに外径用の旋削チップがありません</translation>
        </message>
        <message>
            <source>reaches every element; smallest nose radius of those that do</source>
            <translation>すべての要素に届きます。届くもののうちノーズ半径が最小</translation>
        </message>
        <message>
            <source>reaches all but {} element(s); smallest nose radius of those that reach most</source>
            <translation>届かない要素が {} 個あります。最も多く届くもののうちノーズ半径が最小</translation>
        </message>
        <message>
            <source>widest grooving blade not wider than the groove ({})</source>
            <translation>溝幅 ({}) を超えない最も広い溝入れバイト</translation>
        </message>
        <message>
            <source>narrowest grooving blade; it reaches {} from the air beside it</source>
            <translation>最も狭い溝入れバイト。横の空間から {} に届きます</translation>
        </message>
        <message>
            <source>narrowest parting blade for {}</source>
            <translation>{} に使える最も狭い突切りバイト</translation>
        </message>
        <message>
            <source>{} is not an inside turning insert</source>
            <translation>{} は内径用の旋削チップではありません</translation>
        </message>
        <message>
            <source>{} is not an outside turning insert</source>
            <translation>{} は外径用の旋削チップではありません</translation>
        </message>
        <message>
            <source>largest nose radius for its side (the strongest edge)</source>
            <translation>その側で最大のノーズ半径 (最も強い刃先)</translation>
        </message>
        <message>
            <source>external threading insert for pitch {}</source>
            <translation>ピッチ {} 用の外径ねじ切りチップ</translation>
        </message>
        <message>
            <source>plane</source>
            <translation>平面</translation>
        </message>
        <message>
            <source>cylinder</source>
            <translation>円筒面</translation>
        </message>
        <message>
            <source>cone</source>
            <translation>円錐面</translation>
        </message>
        <message>
            <source>sphere</source>
            <translation>球面</translation>
        </message>
        <message>
            <source>torus</source>
            <translation>トーラス面</translation>
        </message>
        <message>
            <source>surface of revolution</source>
            <translation>回転面</translation>
        </message>
        <message>
            <source>Bézier surface</source>
            <translation>ベジェ曲面</translation>
        </message>
        <message>
            <source>B-spline surface</source>
            <translation>B スプライン曲面</translation>
        </message>
        <message>
            <source>extruded surface</source>
            <translation>押し出し面</translation>
        </message>
        <message>
            <source>offset surface</source>
            <translation>オフセット面</translation>
        </message>
        <message>
            <source>free-form surface</source>
            <translation>自由曲面</translation>
        </message>
        <message>
            <source>cannot open it (no such file)</source>
            <translation>開けません (ファイルがありません)</translation>
        </message>
        <message>
            <source>not a STEP file, or a broken one</source>
            <translation>STEP ファイルでないか、壊れています</translation>
        </message>
        <message>
            <source>the file holds no solid: a turned part is imported from its solid model</source>
            <translation>ファイルにソリッドがありません: 旋削部品はソリッドモデルから取り込みます</translation>
        </message>
        <message>
            <source>the file holds {} solids; import one turned part at a time</source>
            <translation>ファイルに {} 個のソリッドがあります。旋削部品は 1 つずつ取り込んでください</translation>
        </message>
        <message>
            <source>not a body of revolution: face {} is a {}, not turned about an axis</source>
            <translation>回転体ではありません: 面 {} は{}で、軸のまわりに回転した面ではありません</translation>
        </message>
        <message>
            <source>not a body of revolution: no face of it is turned about an axis (cylinder, cone, torus, sphere)</source>
            <translation>回転体ではありません: 軸のまわりに回転した面 (円筒面、円錐面、トーラス面、球面) がありません</translation>
        </message>
        <message>
            <source>not a body of revolution: face {} (a {}) is not turned about the axis of face {} (a {})</source>
            <translation>回転体ではありません: 面 {0} ({1}) が面 {2} ({3}) の軸のまわりに回転していません</translation>
        </message>
        <message>
            <source>not a body of revolution: face {} (a {}) is not centred on the axis of face {} (a {})</source>
            <translation>回転体ではありません: 面 {0} ({1}) の中心が面 {2} ({3}) の軸上にありません</translation>
        </message>
        <message>
            <source>not a body of revolution: face {} (a {}) is not square to the axis of face {} (a {})</source>
            <translation>回転体ではありません: 面 {0} ({1}) が面 {2} ({3}) の軸に直角ではありません</translation>
        </message>
        <message>
            <source>OpenCASCADE could not cut the part with the half-plane</source>
            <translation>OpenCASCADE で部品を半平面で切断できませんでした</translation>
        </message>
        <message>
            <source>the half-section has an edge that is neither a line nor an arc</source>
            <translation>半断面に直線でも円弧でもない辺があります</translation>
        </message>
        <message>
            <source>the half-plane through the axis does not cut the part</source>
            <translation>軸を通る半平面が部品と交わりません</translation>
        </message>
        <message>
            <source>the half-section's outline does not close</source>
            <translation>半断面の輪郭が閉じていません</translation>
        </message>
        <message>
            <source>the half-section falls into several pieces (a closed cavity inside the part?)</source>
            <translation>半断面がいくつかに分かれています (部品内部に閉じた空洞がありますか?)</translation>
        </message>
        <message>
            <source>{}: OpenCASCADE failed reading it: {}</source>
            <translation>{}: OpenCASCADE が読み込みに失敗しました: {}</translation>
        </message>
        <message>
            <source>paths {} and {}, points {} to {} (X {:.3f} Y {:.3f} Z {:.3f}): the surface turns under itself; the verifying simulation is a height field and cannot see undercuts</source>
            <translation>パス {}・{} の点 {}～{} (X {} Y {} Z {}): 曲面が自身の下に回り込んでいます。検証シミュレーションは高さマップなので、アンダーカットは見えません</translation>
        </message>
        <message>
            <source>path {}, point {} (X {:.3f} Y {:.3f} Z {:.3f})</source>
            <translation>パス {} の点 {} (X {} Y {} Z {})</translation>
        </message>
        <message>
            <source>projection {} ({}): {}</source>
            <translation>投影 {} ({}): {}</translation>
        </message>
        <message>
            <source>it needs at least two points, it has {}</source>
            <translation>2 点以上必要ですが、{} 点しかありません</translation>
        </message>
        <message>
            <source>projection {} ({}), point {} ({} {:.4f}): {} must rise or fall all along the curve, it {} after point {}</source>
            <translation>投影 {0} ({1}) の点 {2} ({3} {4}): {5} は曲線全体で増え続けるか減り続けなければなりませんが、点 {7} の後で{6}</translation>
        </message>
        <message>
            <source>stands still</source>
            <translation>変わっていません</translation>
        </message>
        <message>
            <source>turns back</source>
            <translation>逆戻りしています</translation>
        </message>
        <message>
            <source>the division step must be above 0, not {}</source>
            <translation>分割ピッチは 0 より大きくしてください ({} ではなく)</translation>
        </message>
        <message>
            <source>projection 2 lies in the same plane ({}) as projection 1: a space curve needs two planes</source>
            <translation>投影 2 が投影 1 と同じ平面 ({}) にあります。空間曲線には 2 つの平面が必要です</translation>
        </message>
        <message>
            <source>projection 2 ({}): its {} range {:.4f} to {:.4f} does not overlap projection 1's ({}) {:.4f} to {:.4f}</source>
            <translation>投影 2 ({}): {} の範囲 {}～{} が投影 1 ({}) の {}～{} と重なりません</translation>
        </message>
        <message>
            <source>projections {} and {}: OpenCASCADE refused them ({})</source>
            <translation>投影 {} と {}: OpenCASCADE が受け付けませんでした ({})</translation>
        </message>
        <message>
            <source>the step-over must be above 0, not {}</source>
            <translation>曲線に沿ったピッチは 0 より大きくしてください ({} ではなく)</translation>
        </message>
        <message>
            <source>it needs at least two points</source>
            <translation>2 点以上必要です</translation>
        </message>
        <message>
            <source>OpenCASCADE could not measure it ({})</source>
            <translation>OpenCASCADE で長さを測れませんでした ({})</translation>
        </message>
        <message>
            <source>curve 1: {}</source>
            <translation>曲線 1: {}</translation>
        </message>
        <message>
            <source>curve 2: {}</source>
            <translation>曲線 2: {}</translation>
        </message>
        <message>
            <source>the curve: {}</source>
            <translation>曲線: {}</translation>
        </message>
        <message>
            <source>it must be divided into at least 1 piece, not {}</source>
            <translation>1 つ以上に分割してください ({} ではなく)</translation>
        </message>
        <message>
            <source>points {} and {} are the same point</source>
            <translation>点 {} と点 {} が同じ点です</translation>
        </message>
        <message>
            <source>OpenCASCADE could not divide it into {} pieces</source>
            <translation>OpenCASCADE で {} 個に分割できませんでした</translation>
        </message>
        <message>
            <source>OpenCASCADE refused it ({})</source>
            <translation>OpenCASCADE が受け付けませんでした ({})</translation>
        </message>
        <message>
            <source>the spacing {} must be above 0</source>
            <translation>間隔 {} は 0 より大きくしてください</translation>
        </message>
        <message>
            <source>{}: a face lies under another at {} (Z {:.3f} under Z {:.3f}); a surface machined from above has none (the verifying simulation is a height field)</source>
            <translation>{}: {} で面が別の面の下にあります (Z {} が Z {} の下)。上から削る曲面にこれがあってはなりません (検証シミュレーションは高さマップです)</translation>
        </message>
        <message>
            <source>{}: {} × {} points at a spacing of {} mm; a surface holds at most {} (give a larger spacing)</source>
            <translation>{0}: 間隔 {3} mm では {1} × {2} 点になります。曲面は最大 {4} 点までです (間隔を大きくしてください)</translation>
        </message>
        <message>
            <source>{}: no face lies under {}: the faces seen from above leave a hole or are not a rectangle; the surface must cover its X-Y rectangle</source>
            <translation>{}: {} の下に面がありません。上から見た面に穴があるか、長方形になっていません。曲面は X-Y の長方形全体を覆う必要があります</translation>
        </message>
        <message>
            <source>N: the roughing surface needs at least 1 piece, not {}</source>
            <translation>N: 荒加工の曲面には 1 つ以上の分割が必要です ({} ではなく)</translation>
        </message>
        <message>
            <source>M: the finishing surface's pieces (M = {}) must be more than the roughing surface's (N = {})</source>
            <translation>M: 仕上げの曲面の分割数 (M = {}) は荒加工の曲面の分割数 (N = {}) より多くしてください</translation>
        </message>
        <message>
            <source>the ruled surface needs two curves of the same number of points, at least two</source>
            <translation>線織面には同じ点数 (2 点以上) の曲線が 2 本必要です</translation>
        </message>
        <message>
            <source>the ruled surface is not a plane within {} mm</source>
            <translation>線織面が {} mm 以内で平面になっていません</translation>
        </message>
        <message>
            <source>the ruled surface: OpenCASCADE refused it ({})</source>
            <translation>線織面: OpenCASCADE が受け付けませんでした ({})</translation>
        </message>
        <message>
            <source>the surface's paths: at least 2 paths of 2 points are needed, there are {}</source>
            <translation>曲面のパス: 2 点以上のパスが少なくとも 2 本必要ですが、{} 本です</translation>
        </message>
        <message>
            <source>the surface's paths: path {} has {} points, path 1 has {}</source>
            <translation>曲面のパス: パス {} の点は {} 個ですが、パス 1 は {} 個です</translation>
        </message>
        <message>
            <source>the surface's paths: OpenCASCADE could not interpolate them</source>
            <translation>曲面のパス: OpenCASCADE で補間できませんでした</translation>
        </message>
        <message>
            <source>{}: OpenCASCADE could not put the surface into STEP</source>
            <translation>{}: OpenCASCADE で曲面を STEP に変換できませんでした</translation>
        </message>
        <message>
            <source>{}: the STEP file could not be written</source>
            <translation>{}: STEP ファイルを書き込めませんでした</translation>
        </message>
        <message>
            <source>{}: OpenCASCADE refused the surface ({})</source>
            <translation>{}: OpenCASCADE が曲面を受け付けませんでした ({})</translation>
        </message>
        <message>
            <source>no temporary folder for the STEP file: {}</source>
            <translation>STEP ファイル用の一時フォルダがありません: {}</translation>
        </message>
        <message>
            <source>{}: the STEP file written could not be read back</source>
            <translation>{}: 書き込んだ STEP ファイルを読み戻せませんでした</translation>
        </message>
        <message>
            <source>{}: no such file</source>
            <translation>{}: ファイルがありません</translation>
        </message>
        <message>
            <source>{}: not a STEP file OpenCASCADE can read</source>
            <translation>{}: OpenCASCADE で読める STEP ファイルではありません</translation>
        </message>
        <message>
            <source>{}: the STEP file holds no shape</source>
            <translation>{}: STEP ファイルに形状がありません</translation>
        </message>
        <message>
            <source>{}: the STEP file holds no face</source>
            <translation>{}: STEP ファイルに面がありません</translation>
        </message>
        <message>
            <source>{}: its {} faces gave no triangles</source>
            <translation>{}: {} 個の面から三角形が作れませんでした</translation>
        </message>
        <message>
            <source>{}: OpenCASCADE refused it ({})</source>
            <translation>{}: OpenCASCADE が受け付けませんでした ({})</translation>
        </message>
        <message>
            <source>{} to {}</source>
            <translation>{}～{}</translation>
        </message>
        <message>
            <source>{} and {}</source>
            <translation>{}、{}</translation>
        </message>
        <message>
            <source>work offset '{}' cannot be posted for {}: {}; {} offers {}</source>
            <translation>ワーク座標系 '{0}' は {1} に出力できません: {2}。{3} で使えるのは {4} です</translation>
        </message>
        <message>
            <source>{} has no {}</source>
            <translation>{} には {} がありません</translation>
        </message>
        <message>
            <source>G154 P (Haas' extended work offsets)</source>
            <translation>G154 P (Haas の追加ワーク座標系)</translation>
        </message>
        <message>
            <source>G54.1 P (FANUC's extended work offsets)</source>
            <translation>G54.1 P (FANUC の追加ワーク座標系)</translation>
        </message>
        <message>
            <source>there is no {}</source>
            <translation>{} はありません</translation>
        </message>
        <message>
            <source>not a work offset</source>
            <translation>ワーク座標系ではありません</translation>
        </message>
        <message>
            <source>the SINUMERIK manual pages at hand do not say which probe edge MEAS=1 and MEAS=-1 take, how $AC_MEA reports a touch not made, nor that STOPRE must come before $AA_MW is read; see docs/probing.md</source>
            <translation>手元の SINUMERIK マニュアルには、MEAS=1 と MEAS=-1 がどちらのプローブエッジを取るか、タッチしなかったときに $AC_MEA がどう報告するか、$AA_MW を読む前に STOPRE が必要かどうかが書かれていません。docs/probing.md を参照してください</translation>
        </message>
        <message>
            <source>the TNC manual pages at hand do not say what TCH PROBE 0 does when nothing is touched, and the one way found to write a preset from a program, FN 17: SYSWRITE, is locked behind the machine maker's code number; see docs/probing.md</source>
            <translation>手元の TNC マニュアルには、何もタッチしなかったときに TCH PROBE 0 がどう動くかが書かれていません。また、プログラムからプリセットを書き込む唯一の方法 FN 17: SYSWRITE は機械メーカーのコード番号で保護されています。docs/probing.md を参照してください</translation>
        </message>
        <message>
            <source>the {} dialect writes no lathe tapes (Klartext is a milling control's language); {} can</source>
            <translation>NC 形式 {} は旋盤のテープを出力しません (Klartext はフライス盤制御の言語です)。出力できるのは {} です</translation>
        </message>
        <message>
            <source>the {} dialect writes no probing unit's programs; {} can ({})</source>
            <translation>NC 形式 {} は測定ユニットのプログラムを出力しません。出力できるのは {} です ({})</translation>
        </message>
        <message>
            <source>machine: {} is a two-path lathe and the job has no roughing step to balance between its paths</source>
            <translation>machine: {} は2系統旋盤ですが、ジョブに系統間で振り分ける荒加工工程がありません</translation>
        </message>
        <message>
            <source>ER32 collet chuck</source>
            <translation>ER32 コレットチャック</translation>
        </message>
        <message>
            <source>Tapping chuck ER32</source>
            <translation>タッパーチャック ER32</translation>
        </message>
        <message>
            <source>HSK63 shrink-fit</source>
            <translation>HSK63 焼きばめ</translation>
        </message>
        <message>
            <source>HSK63 boring head</source>
            <translation>HSK63 ボーリングヘッド</translation>
        </message>
        <message>
            <source>GHDR 26-3 parting</source>
            <translation>GHDR 26-3 突切り</translation>
        </message>
        <message>
            <source>ER16 collet chuck</source>
            <translation>ER16 コレットチャック</translation>
        </message>
        <message>
            <source>Weldon side lock</source>
            <translation>サイドロック(ウェルドン)</translation>
        </message>
        <message>
            <source>HSK63 shell mill arbor</source>
            <translation>HSK63 シェルミルアーバ</translation>
        </message>
        <message>
            <source>HSK63 probe body</source>
            <translation>HSK63 プローブ本体</translation>
        </message>
        <message>
            <source>reading the history of tool T{}</source>
            <translation>工具 T{} の履歴の読み込み</translation>
        </message>
        <message>
            <source>{}: job '{}': a name, and text without NUL characters, are needed</source>
            <translation>{}: ジョブ '{}': 名前と、NUL 文字を含まないテキストが必要です</translation>
        </message>
        <message>
            <source>job '{}' is open at station {} (by {} since {}); it was not saved</source>
            <translation>ジョブ '{}' はステーション {} で開かれています（{}、{} から）。保存されませんでした</translation>
        </message>
        <message>
            <source>{}: saving job '{}' failed ({})</source>
            <translation>{}: ジョブ '{}' の保存に失敗しました（{}）</translation>
        </message>
        <message>
            <source>{}: opening job '{}' failed ({})</source>
            <translation>{}: ジョブ '{}' を開けませんでした（{}）</translation>
        </message>
        <message>
            <source>{} has no version {} of job '{}'</source>
            <translation>{} にはバージョン {} のジョブ '{}' がありません</translation>
        </message>
        <message>
            <source>{} has no job '{}'</source>
            <translation>{} にジョブ '{}' はありません</translation>
        </message>
        <message>
            <source>{}: reading the history of job '{}' failed ({})</source>
            <translation>{}: ジョブ '{}' の履歴を読めませんでした（{}）</translation>
        </message>
        <message>
            <source>{}: listing the jobs failed ({})</source>
            <translation>{}: ジョブの一覧を取得できませんでした（{}）</translation>
        </message>
        <message>
            <source>{}: locking job '{}' failed ({})</source>
            <translation>{}: ジョブ '{}' をロックできませんでした（{}）</translation>
        </message>
        <message>
            <source>job '{}' is open at station {} (by {} since {})</source>
            <translation>ジョブ '{}' はステーション {} で開かれています（{}、{} から）</translation>
        </message>
        <message>
            <source>{}: unlocking job '{}' failed ({})</source>
            <translation>{}: ジョブ '{}' のロックを解除できませんでした（{}）</translation>
        </message>
        <message>
            <source>job '{}' is open at station {} (by {} since {}) and that station is connected to the server now; its lock was not released</source>
            <translation>ジョブ '{}' はステーション {} で開かれており（{}、{} から）、そのステーションは現在サーバーに接続しています。ロックは解除されませんでした</translation>
        </message>
        <message>
            <source>{}: the local copy {} could not be written</source>
            <translation>{}: ローカルコピー {} を書き込めませんでした</translation>
        </message>
        <message>
            <source>{}: the local copy {} could not be written ({})</source>
            <translation>{}: ローカルコピー {} を書き込めませんでした（{}）</translation>
        </message>
        <message>
            <source>{} cannot be reached ({}) and this station has no copy of its tools yet</source>
            <translation>{} に接続できません（{}）。このステーションにはまだ工具のコピーがありません</translation>
        </message>
        <message>
            <source>{} cannot be reached ({}): the tools are as of {} and cannot be edited until it is back</source>
            <translation>{} に接続できません（{}）。工具は {} 時点のもので、接続が戻るまで編集できません</translation>
        </message>
        <message>
            <source>tools as of {} (read only: {} cannot be reached)</source>
            <translation>{} 時点の工具（読み取り専用: {} に接続できません）</translation>
        </message>
        <message>
            <source>tools: {}</source>
            <translation>工具: {}</translation>
        </message>
        <message>
            <source>{}: tool T{} ({}): {}</source>
            <translation>{}: 工具 T{} ({}): {}</translation>
        </message>
        <message>
            <source>{}: tool T{} ({}) holds a NUL character, which the server cannot store</source>
            <translation>{}: 工具 T{}（{}）に NUL 文字が含まれています。サーバーには保存できません</translation>
        </message>
        <message>
            <source>saving tool T{}</source>
            <translation>工具 T{} の保存</translation>
        </message>
        <message>
            <source>reading tool T{}</source>
            <translation>工具 T{} の読み込み</translation>
        </message>
        <message>
            <source>{} has no tool T{}</source>
            <translation>{} に工具 T{} がありません</translation>
        </message>
        <message>
            <source>removing tool T{}</source>
            <translation>工具 T{} の削除</translation>
        </message>
        <message>
            <source>adding usage to tool T{}</source>
            <translation>工具 T{} への使用時間の加算</translation>
        </message>
        <message>
            <source>{} cannot be read ({})</source>
            <translation>{} を読めません（{}）</translation>
        </message>
        <message>
            <source>tool T{} ({}) holds a NUL character</source>
            <translation>工具 T{}（{}）に NUL 文字が含まれています</translation>
        </message>
        <message>
            <source>importing {}</source>
            <translation>{} の取り込み</translation>
        </message>
        <message>
            <source>{}: {} failed ({})</source>
            <translation>{}: {} に失敗しました（{}）</translation>
        </message>
        <message>
            <source>{} was set up by a newer Taiwa (schema version {}); this program knows version {}</source>
            <translation>{} は新しい Taiwa で作成されています（スキーマ バージョン {}）。このプログラムはバージョン {} まで対応します</translation>
        </message>
        <message>
            <source>{}: the schema could not be brought from version {} to {} ({}); a station's role may only read and write, the owner upgrades it (docs/shop-server.md)</source>
            <translation>{}: スキーマをバージョン {} から {} に更新できませんでした（{}）。ステーションのロールは読み書きのみ可能で、更新は所有者が行います（docs/shop-server.md）</translation>
        </message>
        <message>
            <source>TAIWA_TOOL_DB: '{}' is not a server address ({})</source>
            <translation>TAIWA_TOOL_DB: '{}' はサーバーのアドレスではありません（{}）</translation>
        </message>
        <message>
            <source>TAIWA_TOOL_DB: the address of {} holds a password; put it in ~/.pgpass or the service file instead (docs/shop-server.md)</source>
            <translation>TAIWA_TOOL_DB: {} のアドレスにパスワードが含まれています。~/.pgpass かサービスファイルに書いてください（docs/shop-server.md）</translation>
        </message>
        <message>
            <source>the name says {:g} mm, the diameter is {:g} mm</source>
            <translation>名前は {:g} mm を示していますが、直径は {:g} mm です</translation>
        </message>
        <message>
            <source>T number {} must be 1 to {}</source>
            <translation>T 番号 {} は 1 ～ {} にしてください</translation>
        </message>
        <message>
            <source>diameter {:g} mm is more than 500 mm</source>
            <translation>径 {} mm が 500 mm を超えています</translation>
        </message>
        <message>
            <source>corner radius {:g} mm must not be negative</source>
            <translation>コーナ半径 {} mm は負にできません</translation>
        </message>
        <message>
            <source>corner radius {:g} mm is more than half the diameter ({:g} mm)</source>
            <translation>コーナ半径 {} mm が径の半分 ({} mm) を超えています</translation>
        </message>
        <message>
            <source>taper {:g}° per side must be 0 to less than 45°</source>
            <translation>片側テーパ {}° は 0 以上 45° 未満にしてください</translation>
        </message>
        <message>
            <source>flute length {:g} mm must not be negative</source>
            <translation>刃長 {} mm は負にできません</translation>
        </message>
        <message>
            <source>holder Ø {:g} mm must not be negative</source>
            <translation>ホルダ径 Ø {} mm は負にできません</translation>
        </message>
        <message>
            <source>holder Ø {:g} mm is narrower than the tool (Ø {:g} mm)</source>
            <translation>ホルダ径 Ø {} mm が工具 (Ø {} mm) より細くなっています</translation>
        </message>
        <message>
            <source>holder length {:g} mm must not be negative</source>
            <translation>ホルダ長 {} mm は負にできません</translation>
        </message>
        <message>
            <source>stick-out {:g} mm must not be negative</source>
            <translation>突出し長 {} mm は負にできません</translation>
        </message>
        <message>
            <source>stick-out {:g} mm is shorter than the flutes ({:g} mm)</source>
            <translation>突出し長 {} mm が刃長 ({} mm) より短くなっています</translation>
        </message>
        <message>
            <source>a tap's pitch {:g} mm must be greater than zero, at most 10 mm (one pitch)</source>
            <translation>タップのピッチ {} mm は 0 より大きく 10 mm 以下にしてください (1 ピッチ)</translation>
        </message>
        <message>
            <source>life {:g} min must not be negative</source>
            <translation>寿命 {} 分は負にできません</translation>
        </message>
        <message>
            <source>used {:g} min must not be negative</source>
            <translation>使用時間 {} 分は負にできません</translation>
        </message>
        <message>
            <source>it is a {}, the step needs a {}</source>
            <translation>この工具は{}ですが、工程には{}が必要です</translation>
        </message>
        <message>
            <source>it has no cutting data for {}</source>
            <translation>{} の切削条件がありません</translation>
        </message>
        <message>
            <source>its taper is {:g} deg per side, the wall's is {:g}</source>
            <translation>工具のテーパは片側 {} 度、壁は {} 度です</translation>
        </message>
        <message>
            <source>its radius {:g} mm is larger than the corner radius {:g} mm</source>
            <translation>工具半径 {} mm がコーナ半径 {} mm より大きくなっています</translation>
        </message>
        <message>
            <source>it does not cut at its centre, so it cannot ramp in without a pilot hole</source>
            <translation>センターカットがないので、下穴なしではランプで切り込めません</translation>
        </message>
        <message>
            <source>its diameter {:g} mm is too large for the pocket</source>
            <translation>工具径 {} mm はポケットに対して大きすぎます</translation>
        </message>
        <message>
            <source>its diameter {:g} mm is smaller than the {:g} mm needed</source>
            <translation>工具径 {} mm が必要な {} mm より小さくなっています</translation>
        </message>
        <message>
            <source>its flutes ({:g} mm) are shorter than the depth {:g} mm</source>
            <translation>刃長 ({} mm) が深さ {} mm より短くなっています</translation>
        </message>
        <message>
            <source>its stick-out ({:g} mm) is shorter than the depth {:g} mm</source>
            <translation>突出し長 ({} mm) が深さ {} mm より短くなっています</translation>
        </message>
        <message>
            <source>no taper end mill of {:g} deg per side in the tool library for the {}</source>
            <translation>{1}用の片側 {0} 度のテーパエンドミルが工具ライブラリにありません</translation>
        </message>
        <message>
            <source>no {} in the tool library for the {}</source>
            <translation>{1}用の{0}が工具ライブラリにありません</translation>
        </message>
        <message>
            <source>no {} in the tool library fits the {}: T{} ({}) is the nearest, but {}</source>
            <translation>工具ライブラリには{1}に使える{0}がありません。最も近いのは T{2} ({3}) ですが、{4}</translation>
        </message>
        <message>
            <source>{} is a folder, not a tool library (give the library's file)</source>
            <translation>{} はフォルダで、工具ライブラリではありません (ライブラリのファイルを指定してください)</translation>
        </message>
        <message>
            <source>{} is not a regular file, not a tool library</source>
            <translation>{} は通常のファイルではなく、工具ライブラリではありません</translation>
        </message>
        <message>
            <source>{} is empty, not a tool library (delete it to have the default library created)</source>
            <translation>{} は空で、工具ライブラリではありません (削除すると既定のライブラリが作成されます)</translation>
        </message>
        <message>
            <source>cannot create the folder of the tool library {}: {}</source>
            <translation>工具ライブラリ {} のフォルダを作成できません: {}</translation>
        </message>
        <message>
            <source>{} was written by a newer Taiwa (tool library version {}); this program reads version {}</source>
            <translation>{} は新しい Taiwa で書かれています (工具ライブラリのバージョン {})。このプログラムが読めるのはバージョン {} です</translation>
        </message>
        <message>
            <source>{} is an SQLite database but not a tool library</source>
            <translation>{} は SQLite データベースですが、工具ライブラリではありません</translation>
        </message>
        <message>
            <source>{} (while upgrading it from tool library version {})</source>
            <translation>{} (工具ライブラリをバージョン {} から更新中)</translation>
        </message>
        <message>
            <source>{}: tool {}: {} is '{}', not a number</source>
            <translation>{}: 工具 {}: {} が '{}' で、数値ではありません</translation>
        </message>
        <message>
            <source>{} is not a tool library (the file is not an SQLite database)</source>
            <translation>{} は工具ライブラリではありません (SQLite データベースではありません)</translation>
        </message>
        <message>
            <source>{} is locked by another program; close it and try again</source>
            <translation>{} は別のプログラムがロックしています。そのプログラムを閉じてからやり直してください</translation>
        </message>
        <message>
            <source>{} cannot be opened for writing ({})</source>
            <translation>{} を書き込み用に開けません ({})</translation>
        </message>
        <message>
            <source>{} is damaged ({}); restore it from a backup</source>
            <translation>{} は破損しています ({})。バックアップから復元してください</translation>
        </message>
        <message>
            <source>T{} ({:g} mm {}) reaches its life during step {} (unit {} {}): {:.1f} min left, the step needs {:.1f} min; change it for a fresh one before that step</source>
            <translation>T{0} ({1} mm {2}) は工程 {3} (ユニット {4} {5}) の途中で寿命に達します: 残り {6} 分、工程には {7} 分必要です。その工程の前に新しい工具に交換してください</translation>
        </message>
        <message>
            <source>{}: tool {} has an unknown type '{}'</source>
            <translation>{}: 工具 {} の種類 '{}' が不明です</translation>
        </message>
        <message>
            <source>{}: tool {} has unreadable lathe data '{}'</source>
            <translation>{}: 工具 {} の旋削データ '{}' を読めません</translation>
        </message>
        <message>
            <source>allowance row {}: there is no edge {} in the profile</source>
            <translation>取り代の行 {}: 形状に要素 {} がありません</translation>
        </message>
        <message>
            <source>allowance row {}: {} already has an allowance in row {}</source>
            <translation>取り代の行 {}: {} にはすでに行 {} で取り代があります</translation>
        </message>
        <message>
            <source>allowance row {}: the allowance must be above zero</source>
            <translation>取り代の行 {}: 取り代は 0 より大きくしてください</translation>
        </message>
        <message>
            <source>allowance row {}: the adjustment cannot be below zero</source>
            <translation>取り代の行 {}: 調整量は負にできません</translation>
        </message>
        <message>
            <source>allowance row {}: a groove width must be above zero</source>
            <translation>取り代の行 {}: 溝幅は 0 より大きくしてください</translation>
        </message>
        <message>
            <source>allowance row {}: a groove depth must be above zero</source>
            <translation>取り代の行 {}: 溝深さは 0 より大きくしてください</translation>
        </message>
        <message>
            <source>the allowances and grooves split the part into {} pieces</source>
            <translation>取り代と溝で部品が {} 個に分かれます</translation>
        </message>
        <message>
            <source>internal: a piece of the deformed profile at Z{} X{} lies on no edge; please report this job</source>
            <translation>内部エラー: 変形した形状の Z{} X{} の部分がどの要素にも乗っていません。このジョブを報告してください</translation>
        </message>
        <message>
            <source>allowance row {}: a {} groove at the corner of {} and {} would lie in {}, which has no grinding allowance; a relief groove only takes allowance off</source>
            <translation>取り代の行 {0}: {2} と {3} の角の{1}溝は研削取り代のない {4} に入ります。逃げ溝は取り代だけを削ります</translation>
        </message>
        <message>
            <source>allowance row {}: a {} groove {} wide and {} deep takes {} of {}, which is {} long</source>
            <translation>取り代の行 {0}: 幅 {2}、深さ {3} の{1}溝が長さ {6} の {5} のうち {4} を占めます</translation>
        </message>
        <message>
            <source>allowance row {}: a groove {} deep at {} reaches the axis; it is deeper than the part allows</source>
            <translation>取り代の行 {0}: {2} の深さ {1} の溝が軸に達します。部品が許すより深くなっています</translation>
        </message>
        <message>
            <source>allowance row {}: a groove {} deep at {} reaches {}; it is deeper than the part allows</source>
            <translation>取り代の行 {0}: {2} の深さ {1} の溝が {3} に達します。部品が許すより深くなっています</translation>
        </message>
        <message>
            <source>allowance row {}: the moved {} and the moved {} do not meet</source>
            <translation>取り代の行 {}: 移動した {} と移動した {} が交わりません</translation>
        </message>
        <message>
            <source>allowance row {}: {} meets {} at a tangent joint, where the tool's nose radius leaves a ridge; give the adjustment, or add a finishing turning tool to the library so that its nose radius is taken</source>
            <translation>取り代の行 {}: {} と {} が接線でつながり、そこに工具のノーズ半径で段が残ります。調整量を指定するか、ノーズ半径を使えるよう仕上げ用旋削工具をライブラリに追加してください</translation>
        </message>
        <message>
            <source>allowance row {}: an adjustment of {} is not shorter than {} ({} long)</source>
            <translation>取り代の行 {}: 調整量 {} が {} (長さ {}) より短くありません</translation>
        </message>
        <message>
            <source>allowance row {}: the tangent of {} does not reach the moved {}</source>
            <translation>取り代の行 {}: {} の接線が移動した {} に届きません</translation>
        </message>
        <message>
            <source>allowance row {}: an allowance of {} on {} reaches past the end of its neighbour {} ({} long); the edges would cross</source>
            <translation>取り代の行 {0}: {2} の取り代 {1} が隣の {3} (長さ {4}) の端を越えます。要素どうしが交差します</translation>
        </message>
        <message>
            <source>allowance row {}: {} is an arc of radius {}; an allowance of {} leaves it no radius</source>
            <translation>取り代の行 {}: {} は半径 {} の円弧です。取り代 {} では半径がなくなります</translation>
        </message>
        <message>
            <source>allowance row {}: with an allowance of {} the moved {} vanishes between its neighbours; the edges would cross</source>
            <translation>取り代の行 {}: 取り代 {} では移動した {} が隣どうしの間で消えます。要素どうしが交差します</translation>
        </message>
        <message>
            <source>allowance row {}: an allowance of {} moves {} into {}; the edges would cross</source>
            <translation>取り代の行 {}: 取り代 {} で {} が {} に食い込みます。要素どうしが交差します</translation>
        </message>
        <message>
            <source>allowance row {}: an allowance of {} moves {} past the axis</source>
            <translation>取り代の行 {}: 取り代 {} で {} が軸を越えます</translation>
        </message>
        <message>
            <source>row {} has the edge id {}, which is not a positive number of its own; every row needs one</source>
            <translation>行 {} の要素番号 {} が固有の正の数ではありません。各行に必要です</translation>
        </message>
        <message>
            <source>the start diameter is {}; a diameter cannot be below zero</source>
            <translation>始点の径が {} です。径は負にできません</translation>
        </message>
        <message>
            <source>row {}: the end point is not a number</source>
            <translation>行 {}: 終点が数値ではありません</translation>
        </message>
        <message>
            <source>row {}: the end diameter is {}; a diameter cannot be below zero</source>
            <translation>行 {}: 終点の径が {} です。径は負にできません</translation>
        </message>
        <message>
            <source>row {} ends where it starts (X{} Z{}): an element needs a length</source>
            <translation>行 {} が始点 (X{} Z{}) で終わっています。要素には長さが必要です</translation>
        </message>
        <message>
            <source>row {}: the centre is {} from the start and {} from the end point; an arc's centre is equally far from both</source>
            <translation>行 {}: 中心が始点から {}、終点から {} の距離にあります。円弧の中心は両方から等距離です</translation>
        </message>
        <message>
            <source>row {}: the radius {} does not match the centre, which is {} from the start</source>
            <translation>行 {}: 半径 {} が中心と合いません。中心は始点から {} の距離です</translation>
        </message>
        <message>
            <source>row {}: an arc's radius must be above zero</source>
            <translation>行 {}: 円弧の半径は 0 より大きくしてください</translation>
        </message>
        <message>
            <source>row {}: a radius of {} cannot reach the end point, which is {} from the start; the radius must be at least {}</source>
            <translation>行 {}: 半径 {} では始点から {} 離れた終点に届きません。半径は {} 以上にしてください</translation>
        </message>
        <message>
            <source>row {}: an arc needs its radius or its centre</source>
            <translation>行 {}: 円弧には半径か中心が必要です</translation>
        </message>
        <message>
            <source>row {}: the arc dips below the axis (to Ø{}); a turned profile stays at or above it</source>
            <translation>行 {}: 円弧が軸の下 (Ø{} まで) に入ります。旋削形状は軸上かその上にとどまります</translation>
        </message>
        <message>
            <source>row {}: a {} needs a next row to meet; there is none</source>
            <translation>行 {}: {}には交わる次の行が必要ですが、ありません</translation>
        </message>
        <message>
            <source>row {}: a {} is made between two lines; row {} is an arc</source>
            <translation>行 {}: {}は 2 本の直線の間に作ります。行 {} は円弧です</translation>
        </message>
        <message>
            <source>row {}: the {} size must be above zero</source>
            <translation>行 {}: {}の大きさは 0 より大きくしてください</translation>
        </message>
        <message>
            <source>row {}: rows {} and {} are in line; there is no corner for a {}</source>
            <translation>行 {}: 行 {} と {} が一直線上にあります。{}を付ける角がありません</translation>
        </message>
        <message>
            <source>row {}: a {} of {} takes {} of both lines; row {} has {} and row {} has {}</source>
            <translation>行 {0}: {2} の{1}は両方の直線から {3} を取ります。行 {4} は {5}、行 {6} は {7} です</translation>
        </message>
        <message>
            <source>the profile is not one chain: {} (row {}) meets {} (row {}) at X{} Z{}</source>
            <translation>形状が一続きではありません: {} (行 {}) が {} (行 {}) と X{} Z{} で交わります</translation>
        </message>
        <message>
            <source>the profile is not one chain around the part: {} (row {}) reaches the line closing it {} at X{} Z{}</source>
            <translation>形状が部品を囲む一続きになっていません: {} (行 {}) が閉じる線 {} に X{} Z{} で達します</translation>
        </message>
        <message>
            <source>the job</source>
            <translation>ジョブ</translation>
        </message>
        <message>
            <source>step {} ({}, unit {})</source>
            <translation>工程 {} ({}、ユニット {})</translation>
        </message>
        <message>
            <source>step {} ({}, unit {} '{}')</source>
            <translation>工程 {} ({}、ユニット {} '{}')</translation>
        </message>
        <message>
            <source>gouge {} deep into the finished part at {}, over {:.3f} mm² of the half-section</source>
            <translation>{1} で仕上がり形状に深さ {0} の削り込み、半断面で {2} mm²</translation>
        </message>
        <message>
            <source>gouge {} deep into the finished part at {}, over {:.3f} mm²</source>
            <translation>{1} で仕上がり形状に深さ {0} の削り込み、面積 {2} mm²</translation>
        </message>
        <message>
            <source>material left up to {} thicker than it should leave, thickest at {}, over {:.3f} mm² of the half-section</source>
            <translation>残すべき量より最大 {} 厚く削り残しがあります。最も厚いのは {}、半断面で {} mm²</translation>
        </message>
        <message>
            <source>material left up to {} above what it should leave, highest at {}, over {:.3f} mm²</source>
            <translation>残すべき量より最大 {} 高く削り残しがあります。最も高いのは {}、面積 {} mm²</translation>
        </message>
        <message>
            <source>the tool's {} runs {} into stock at {}</source>
            <translation>{2} で工具の{0}が素材に {1} 入ります</translation>
        </message>
        <message>
            <source>rapid (G0) {} into stock at {}</source>
            <translation>{1} で早送り (G0) が素材に {0} 入ります</translation>
        </message>
        <message>
            <source>the paths span {} more along {} than the machine '{}' travels</source>
            <translation>工具経路が {1} 方向で機械 '{2}' のストロークより {0} 長くなっています</translation>
        </message>
        <message>
            <source>the tape has a {} the plan does not, to {}, {} into stock</source>
            <translation>テープに計画にない {0} があります: {1} へ、素材に {2} 入ります</translation>
        </message>
        <message>
            <source>the tape has a {} the plan does not, to {}</source>
            <translation>テープに計画にない {0} があります: {1} へ</translation>
        </message>
        <message>
            <source>the tape cannot be read back, so it is not verified from here on: {}</source>
            <translation>テープを読み戻せないため、ここから先は検証されていません: {0}</translation>
        </message>
        <message>
            <source>the wait {} is not met by the other path's program at its turn: both paths would stop there (a deadlock)</source>
            <translation>待ち {} に相手の系統のプログラムが同じ順番で応じません: 両系統がそこで止まります (デッドロック)</translation>
        </message>
        <message>
            <source>{}: {}, in {} at line {}</source>
            <translation>{}: {}、{} の {} 行目</translation>
        </message>
        <message>
            <source>{}: {}, move {}, tape line {}</source>
            <translation>{}: {}、移動 {}、テープ {} 行目</translation>
        </message>
        <message>
            <source>{}: {}, move {}</source>
            <translation>{}: {}、移動 {}</translation>
        </message>
        <message>
            <source>{}: {}, tape line {}</source>
            <translation>{}: {}、テープ {} 行目</translation>
        </message>
        <message>
            <source>holder</source>
            <translation>ホルダ</translation>
        </message>
        <message>
            <source>shank</source>
            <translation>シャンク</translation>
        </message>
        <message>
            <source>verified at {:g} mm, not {:g} mm: on that grid the paths would have swept more than {:.3g} cells; --resolution {:g} verifies on it all the same</source>
            <translation>{:g} mm で検証しました ({:g} mm ではありません): その格子ではパスが {:.3g} セルを超えて掃引するためです。--resolution {:g} を指定するとその格子で検証します</translation>
        </message>
        <message>
            <source>a lathe job with no turning step: nothing to cut</source>
            <translation>旋削工程のない旋盤ジョブ: 削るものがありません</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::Diagnostic</name>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
        <message>
            <source>unit</source>
            <translation>ユニット</translation>
        </message>
        <message>
            <source>%1: job %2: warning: %3</source>
            <translation>%1: ジョブ %2: 警告: %3</translation>
        </message>
        <message>
            <source>%1: job %2: %3</source>
            <translation>%1: ジョブ %2: %3</translation>
        </message>
        <message>
            <source>%1: unit %2 (%3) %4: warning: %5</source>
            <translation>%1: ユニット %2 (%3) %4: 警告: %5</translation>
        </message>
        <message>
            <source>%1: unit %2 (%3) %4: %5</source>
            <translation>%1: ユニット %2 (%3) %4: %5</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::TechnologyDialog</name>
        <message>
            <source>pilot hole stops this far above the floor</source>
            <translation>下穴は底からこの高さで止める</translation>
        </message>
        <message>
            <source>wall allowance left by roughing</source>
            <translation>荒加工の壁仕上げ代</translation>
        </message>
        <message>
            <source>wall allowance of the semi-finish pass (F = 3)</source>
            <translation>中仕上げの壁仕上げ代 (F = 3)</translation>
        </message>
        <message>
            <source>floor allowance left by roughing</source>
            <translation>荒加工の底仕上げ代</translation>
        </message>
        <message>
            <source>roughing layer depth / tool diameter</source>
            <translation>荒加工の1層の深さ / 工具径</translation>
        </message>
        <message>
            <source>roughing step-over / tool diameter</source>
            <translation>荒加工のステップオーバ / 工具径</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::ModulePalette</name>
        <message>
            <source>Add drawn-pass area</source>
            <translation>描いたパスで領域加工を追加</translation>
        </message>
        <message>
            <source>Add contour pocket</source>
            <translation>輪郭ポケットを追加</translation>
        </message>
        <message>
            <source>Add face milling</source>
            <translation>正面フライス削りを追加</translation>
        </message>
        <message>
            <source>Add hole pattern</source>
            <translation>穴パターンを追加</translation>
        </message>
        <message>
            <source>Add M2D 3-D pocket</source>
            <translation>M2D 立体ポケットを追加</translation>
        </message>
        <message>
            <source>Add M4 pocket</source>
            <translation>M4 ポケットを追加</translation>
        </message>
        <message>
            <source>Add work-centre probing</source>
            <translation>ワーク中心の測定を追加</translation>
        </message>
        <message>
            <source>Add side milling</source>
            <translation>側面削りを追加</translation>
        </message>
        <message>
            <source>Add 3-D surface</source>
            <translation>3次元曲面を追加</translation>
        </message>
        <message>
            <source>Add turned profile</source>
            <translation>旋削形状を追加</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::FieldSpec</name>
        <message>
            <source>r1 (corner radius)</source>
            <translation>r1(コーナ半径)</translation>
        </message>
        <message>
            <source>Radius of the pocket's corners; the finishing end mill must fit in it</source>
            <translation>ポケットのコーナー半径；仕上げのエンドミルが入る大きさが必要</translation>
        </message>
        <message>
            <source>T (depth)</source>
            <translation>T(深さ)</translation>
        </message>
        <message>
            <source>Depth of the pocket, down from the top surface</source>
            <translation>ポケットの深さ (上面から下へ)</translation>
        </message>
        <message>
            <source>U (tool use)</source>
            <translation>U(工具使用区分)</translation>
        </message>
        <message>
            <source>Which steps the pocket gets: roughing, floor and wall finishing, or some of them</source>
            <translation>ポケットの工程：荒加工、底面・側壁仕上げ、またはその一部</translation>
        </message>
        <message>
            <source>F (wall finish)</source>
            <translation>F(仕上げ区分)</translation>
        </message>
        <message>
            <source>How the walls are finished: at full depth, in several depths, or in two stages</source>
            <translation>側壁の仕上げ方：全深さで一度に、深さを分けて、または二段階で</translation>
        </message>
        <message>
            <source>H (pilot hole)</source>
            <translation>H(下穴)</translation>
        </message>
        <message>
            <source>Whether a hole is drilled first for the roughing end mill to go down into</source>
            <translation>荒加工のエンドミルが下りる下穴を先にあけるかどうか</translation>
        </message>
        <message>
            <source>Step-over (× D)</source>
            <translation>ステップオーバ(× D)</translation>
        </message>
        <message>
            <source>technology data's</source>
            <translation>技術データの値</translation>
        </message>
        <message>
            <source>Roughing's sideways step as a share of the tool's diameter; empty for the technology data's</source>
            <translation>荒加工の横送り量 (工具径に対する割合)；空欄は加工技術データの値</translation>
        </message>
        <message>
            <source>Islands</source>
            <translation>アイランド</translation>
        </message>
        <message>
            <source>Area</source>
            <translation>領域</translation>
        </message>
        <message>
            <source>The contour of the figure around the area to clear (e.g. K1)</source>
            <translation>除去する領域を囲む図形の輪郭 (例: K1)</translation>
        </message>
        <message>
            <source>Contours of the figure left standing in the area, separated by commas; empty for none</source>
            <translation>領域内に残す図形の輪郭、カンマ区切り。なければ空欄</translation>
        </message>
        <message>
            <source>Depth the passes cut to, down from the top surface</source>
            <translation>パスが削る深さ (上面から下へ)</translation>
        </message>
        <message>
            <source>D (tool diameter)</source>
            <translation>D(工具径)</translation>
        </message>
        <message>
            <source>Diameter of the end mill: each pass is a strip this wide</source>
            <translation>エンドミルの直径: 各パスはこの幅の帯になります</translation>
        </message>
        <message>
            <source>Passes (points)</source>
            <translation>パス(点)</translation>
        </message>
        <message>
            <source>The passes as points X, Y separated by ';' (the tool goes from each to the next); draw them in the Figure tab</source>
            <translation>パスを点 X, Y で ';' 区切りに入力 (工具は点から次の点へ進む)。図形タブで描くこともできます</translation>
        </message>
        <message>
            <source>Outline</source>
            <translation>輪郭</translation>
        </message>
        <message>
            <source>The contour of the figure that is the pocket's edge at the top (e.g. K1)</source>
            <translation>ポケットの上面での縁となる図形の輪郭 (例: K1)</translation>
        </message>
        <message>
            <source>Contours of the figure left standing in the pocket, separated by commas (e.g. K2, K3); empty for none</source>
            <translation>ポケット内に残すアイランドとなる図形の輪郭、カンマ区切り (例: K2, K3)。なければ空欄</translation>
        </message>
        <message>
            <source>Depth</source>
            <translation>深さ</translation>
        </message>
        <message>
            <source>Stock taken off the top, down from Z0; less than the stock's height</source>
            <translation>上面から削り取る量 (Z0 から下へ)。素材高さ未満</translation>
        </message>
        <message>
            <source>Roughing layers and a finishing pass (1), or roughing only leaving the finishing pass (9)</source>
            <translation>荒加工層と仕上げパス (1)、または荒加工のみで仕上げ分を残す (9)</translation>
        </message>
        <message>
            <source>Finishing pass</source>
            <translation>仕上げパス</translation>
        </message>
        <message>
            <source>technology data's β2</source>
            <translation>加工技術データの β2</translation>
        </message>
        <message>
            <source>Depth of the finishing pass, less than the depth; empty for the technology data's β2</source>
            <translation>仕上げパスの深さ (深さ未満)。空欄は加工技術データの β2</translation>
        </message>
        <message>
            <source>Angle of the passes (°)</source>
            <translation>パスの角度 (°)</translation>
        </message>
        <message>
            <source>Direction of the passes in degrees, counter-clockwise from +X</source>
            <translation>パスの方向 (+X から反時計回りの角度)</translation>
        </message>
        <message>
            <source>Pattern</source>
            <translation>配置</translation>
        </message>
        <message>
            <source>One way (every pass climb, back above the part) or zigzag (back and forth, linked beside the part)</source>
            <translation>一方向 (全パスをダウンカット、部品の上を戻る) またはジグザグ (往復、部品の外でつなぐ)</translation>
        </message>
        <message>
            <source>0.75 (face mill), else technology data's</source>
            <translation>0.75 (正面フライス)、それ以外は加工技術データの値</translation>
        </message>
        <message>
            <source>Distance between passes as a share of the tool's diameter, above 0 and at most 0.9</source>
            <translation>パス間隔 (工具径に対する割合、0 より大きく 0.9 以下)</translation>
        </message>
        <message>
            <source>Margin beyond the stock</source>
            <translation>素材外側の余裕</translation>
        </message>
        <message>
            <source>How far the face reaches beyond the stock's sides; 0 for exactly the top</source>
            <translation>面削り範囲が素材側面を越える量。0 は上面ちょうど</translation>
        </message>
        <message>
            <source>How the holes are laid out: one hole, a line, a grid, a bolt circle or an arc</source>
            <translation>穴の配置: 単独、直線、格子、ボルト円、円弧</translation>
        </message>
        <message>
            <source>X (hole, first hole or centre)</source>
            <translation>X (穴、最初の穴または中心)</translation>
        </message>
        <message>
            <source>The hole, the first hole of a line, the corner of a grid, the centre of a circle</source>
            <translation>単独の穴、直線の最初の穴、格子の角、円の中心</translation>
        </message>
        <message>
            <source>Y of the hole, the first hole of a line, the corner of a grid, the centre of a circle</source>
            <translation>穴、列の最初の穴、格子の角、円の中心の Y</translation>
        </message>
        <message>
            <source>Angle (°)</source>
            <translation>角度 (°)</translation>
        </message>
        <message>
            <source>Direction of a line's or grid's rows; angle of a circle's first hole</source>
            <translation>直線・格子の行の方向。円では最初の穴の角度</translation>
        </message>
        <message>
            <source>Pitch</source>
            <translation>ピッチ</translation>
        </message>
        <message>
            <source>Distance between neighbouring holes along the row</source>
            <translation>行に沿って隣り合う穴の間隔</translation>
        </message>
        <message>
            <source>Pitch between rows</source>
            <translation>行間ピッチ</translation>
        </message>
        <message>
            <source>Grid: distance between rows</source>
            <translation>格子: 行と行の間隔</translation>
        </message>
        <message>
            <source>Radius</source>
            <translation>半径</translation>
        </message>
        <message>
            <source>Bolt circle or arc: the radius the hole centres lie on</source>
            <translation>ボルト円・円弧:穴の中心が並ぶ半径</translation>
        </message>
        <message>
            <source>Angular pitch (°)</source>
            <translation>角度ピッチ (°)</translation>
        </message>
        <message>
            <source>Arc: angle between neighbouring holes</source>
            <translation>円弧: 隣り合う穴の間の角度</translation>
        </message>
        <message>
            <source>Count (grid: columns)</source>
            <translation>個数 (格子: 列数)</translation>
        </message>
        <message>
            <source>How many holes: along a line, around a circle or an arc; a grid's columns</source>
            <translation>穴の数:直線上、円周上、円弧上。格子では列数</translation>
        </message>
        <message>
            <source>Rows</source>
            <translation>行数</translation>
        </message>
        <message>
            <source>Grid: how many rows of holes</source>
            <translation>格子:穴の行数</translation>
        </message>
        <message>
            <source>Hole</source>
            <translation>穴</translation>
        </message>
        <message>
            <source>Drilled, tapped, reamed or bored: which steps each hole gets</source>
            <translation>ドリル、タップ、リーマ、中ぐり: 各穴の加工工程</translation>
        </message>
        <message>
            <source>Thread (tapped)</source>
            <translation>ねじ (タップ)</translation>
        </message>
        <message>
            <source>Tapped holes: the ISO metric coarse thread, M3 to M20</source>
            <translation>タップ穴:ISO メートル並目ねじ M3〜M20</translation>
        </message>
        <message>
            <source>Diameter</source>
            <translation>直径</translation>
        </message>
        <message>
            <source>Diameter of a drilled, reamed or bored hole (a tapped hole takes its thread's)</source>
            <translation>ドリル・リーマ・ボーリング穴の直径(タップ穴はねじの径)</translation>
        </message>
        <message>
            <source>Depth (full diameter)</source>
            <translation>深さ (全径部)</translation>
        </message>
        <message>
            <source>Depth of the full diameter (of the full thread), down from the top; the drill point goes deeper</source>
            <translation>全径部 (完全ねじ部) の深さ、上面から下へ。ドリル先端はさらに深くなります</translation>
        </message>
        <message>
            <source>The corner where the opening starts, at the top surface, in work coordinates</source>
            <translation>開口が始まる角、上面でのワーク座標</translation>
        </message>
        <message>
            <source>L1 (length X)</source>
            <translation>L1(X 方向長さ)</translation>
        </message>
        <message>
            <source>Length of the opening along X, at the top surface</source>
            <translation>開口の X 方向の長さ (上面)</translation>
        </message>
        <message>
            <source>L2 (length Y)</source>
            <translation>L2(Y 方向長さ)</translation>
        </message>
        <message>
            <source>Width of the opening along Y, at the top surface</source>
            <translation>開口の Y 方向の幅 (上面)</translation>
        </message>
        <message>
            <source>θ1 (left wall, °)</source>
            <translation>θ1(左壁、°)</translation>
        </message>
        <message>
            <source>Slope of the wall at the start of L1, in degrees from the vertical</source>
            <translation>L1 の始まり側の壁の傾き (垂直からの角度)</translation>
        </message>
        <message>
            <source>θ2 (right wall, °)</source>
            <translation>θ2(右壁、°)</translation>
        </message>
        <message>
            <source>empty = same as θ1</source>
            <translation>空欄 = θ1 と同じ</translation>
        </message>
        <message>
            <source>Slope of the wall at the end of L1, in degrees from the vertical; empty for the same as θ1</source>
            <translation>L1 の終わり側の壁の傾き (垂直からの角度)；空欄は θ1 と同じ</translation>
        </message>
        <message>
            <source>Scallop height</source>
            <translation>カスプ高さ</translation>
        </message>
        <message>
            <source>Largest ridge the ball end mill may leave between its passes on the inclined walls</source>
            <translation>傾斜壁でボールエンドミルのパス間に残ってよい最大のカスプ高さ</translation>
        </message>
        <message>
            <source>A corner of the pocket at the top surface, in work coordinates</source>
            <translation>上面でのポケットの角 (ワーク座標)</translation>
        </message>
        <message>
            <source>S (taper, °/side)</source>
            <translation>S(テーパ、片側 °)</translation>
        </message>
        <message>
            <source>Slope of the walls in degrees per side; 0 for vertical walls</source>
            <translation>壁のテーパ (片側、度)；垂直な壁は 0</translation>
        </message>
        <message>
            <source>Shape</source>
            <translation>形状</translation>
        </message>
        <message>
            <source>Round (a boss or a bore) or rectangular (a block or a pocket)</source>
            <translation>丸形 (ボスまたは穴) か角形 (ブロックまたはポケット)</translation>
        </message>
        <message>
            <source>Touched from</source>
            <translation>接触する側</translation>
        </message>
        <message>
            <source>Whether the probe touches the part from outside or from inside</source>
            <translation>プローブが外側から触れるか内側から触れるか</translation>
        </message>
        <message>
            <source>P1 machine X</source>
            <translation>P1 機械座標 X</translation>
        </message>
        <message>
            <source>Where the first touch is, in machine coordinates</source>
            <translation>最初の測定点の位置 (機械座標)</translation>
        </message>
        <message>
            <source>P1 machine Y</source>
            <translation>P1 機械座標 Y</translation>
        </message>
        <message>
            <source>not touched</source>
            <translation>未測定</translation>
        </message>
        <message>
            <source>A touch, relative to the first one; empty until it is measured</source>
            <translation>最初の点からの相対位置の測定点；測定するまで空欄</translation>
        </message>
        <message>
            <source>P2 side</source>
            <translation>P2 の面</translation>
        </message>
        <message>
            <source>P3 side</source>
            <translation>P3 の面</translation>
        </message>
        <message>
            <source>P4 side</source>
            <translation>P4 の面</translation>
        </message>
        <message>
            <source>P5 side</source>
            <translation>P5 の面</translation>
        </message>
        <message>
            <source>P6 side</source>
            <translation>P6 の面</translation>
        </message>
        <message>
            <source>P7 side</source>
            <translation>P7 の面</translation>
        </message>
        <message>
            <source>P8 side</source>
            <translation>P8 の面</translation>
        </message>
        <message>
            <source>Top face machine Z</source>
            <translation>上面 機械座標 Z</translation>
        </message>
        <message>
            <source>Height of a touch on the top face, in machine coordinates; empty if not touched</source>
            <translation>上面の測定点の高さ (機械座標)；測定しない場合は空欄</translation>
        </message>
        <message>
            <source>Tolerance</source>
            <translation>許容差</translation>
        </message>
        <message>
            <source>Largest distance a touch may lie from the fitted shape</source>
            <translation>測定点が当てはめた形状から離れてよい最大距離</translation>
        </message>
        <message>
            <source>Nominal diameter / width X</source>
            <translation>呼び径 / 幅 X</translation>
        </message>
        <message>
            <source>Diameter of the round part, or its width along X</source>
            <translation>丸形の直径、または X 方向の幅</translation>
        </message>
        <message>
            <source>Nominal length Y</source>
            <translation>呼び長さ Y</translation>
        </message>
        <message>
            <source>Length of the rectangular part along Y</source>
            <translation>角形の Y 方向の長さ</translation>
        </message>
        <message>
            <source>Touch depth</source>
            <translation>接触深さ</translation>
        </message>
        <message>
            <source>How far below the top face the probe touches the sides</source>
            <translation>側面を測定する上面からの深さ</translation>
        </message>
        <message>
            <source>Clearance</source>
            <translation>逃げ量</translation>
        </message>
        <message>
            <source>Distance kept from the part while the probe moves between touches</source>
            <translation>測定点間を移動するときに部品から離す距離</translation>
        </message>
        <message>
            <source>Search distance</source>
            <translation>探索距離</translation>
        </message>
        <message>
            <source>How far past the expected surface the probe looks for it before giving up</source>
            <translation>予想面を越えてどこまで探すか (見つからなければ停止)</translation>
        </message>
        <message>
            <source>Probing feed (mm/min)</source>
            <translation>測定送り (mm/min)</translation>
        </message>
        <message>
            <source>Feed of the probing moves, in mm per minute</source>
            <translation>測定移動の送り (mm/min)</translation>
        </message>
        <message>
            <source>Contour</source>
            <translation>輪郭</translation>
        </message>
        <message>
            <source>The contour of the figure that is the finished wall, open or closed (e.g. K1)</source>
            <translation>仕上がり壁となる図形の輪郭、開いていても閉じていてもよい (例: K1)</translation>
        </message>
        <message>
            <source>Tool side</source>
            <translation>工具側</translation>
        </message>
        <message>
            <source>Which side of the contour, looking along its direction, the tool and the material to remove are on</source>
            <translation>輪郭の方向に見て、工具と除去する材料がどちら側にあるか</translation>
        </message>
        <message>
            <source>Direction</source>
            <translation>方向</translation>
        </message>
        <message>
            <source>Climb or conventional milling (with M3, climb runs the tool on the left of its travel)</source>
            <translation>ダウンカットかアップカット (M3 では、ダウンカットは工具が進行方向の左側)</translation>
        </message>
        <message>
            <source>Depth of the wall, down from the top surface</source>
            <translation>壁の深さ (上面から下へ)</translation>
        </message>
        <message>
            <source>W (width)</source>
            <translation>W(幅)</translation>
        </message>
        <message>
            <source>Width of the material to remove, measured from the contour on the tool's side</source>
            <translation>除去する材料の幅 (工具側で輪郭から測る)</translation>
        </message>
        <message>
            <source>Which steps the wall gets: roughing and finishing, or one of them</source>
            <translation>壁の工程: 荒加工と仕上げ、またはその一方</translation>
        </message>
        <message>
            <source>How the wall is finished: at full depth, or in several depths</source>
            <translation>壁の仕上げ方: 全深さで一度に、または深さを分けて</translation>
        </message>
        <message>
            <source>Curve 1</source>
            <translation>曲線 1</translation>
        </message>
        <message>
            <source>the surface is a STEP face set</source>
            <translation>曲面は STEP の面の集合です</translation>
        </message>
        <message>
            <source>The first curve: points X, Y, Z separated by ';', or two projections 'XY: X, Y; ... / ZX: Z, X; ...', each its points or an open contour of the figure ('XY: K1'); '/ lines' at the end for straight lines</source>
            <translation>1 本目の曲線: ';' で区切った点 X, Y, Z、または 2 つの投影 'XY: X, Y; ... / ZX: Z, X; ...' (各投影は点列か図形の開いた輪郭 'XY: K1')。直線で結ぶときは末尾に '/ lines'</translation>
        </message>
        <message>
            <source>Curve 2</source>
            <translation>曲線 2</translation>
        </message>
        <message>
            <source>The second curve, as the first; the surface is ruled between the two</source>
            <translation>2 本目の曲線 (1 本目と同じ書き方)。曲面は 2 本の間の線織面</translation>
        </message>
        <message>
            <source>N (roughing pieces)</source>
            <translation>N (荒加工の分割数)</translation>
        </message>
        <message>
            <source>Pieces each curve is divided into for the roughing surface; fewer than M</source>
            <translation>荒加工の曲面のために各曲線を分ける数。M より少なく</translation>
        </message>
        <message>
            <source>M (finishing pieces)</source>
            <translation>M (仕上げの分割数)</translation>
        </message>
        <message>
            <source>Pieces each curve is divided into for the finishing surface; more than N; empty: from the step along the curves</source>
            <translation>仕上げの曲面のために各曲線を分ける数。N より多く。空欄: 曲線に沿ったピッチから</translation>
        </message>
        <message>
            <source>Step along the curves (gives M)</source>
            <translation>曲線に沿ったピッチ (M を決める)</translation>
        </message>
        <message>
            <source>M given</source>
            <translation>M を指定</translation>
        </message>
        <message>
            <source>The step along the curves that gives M; empty when M is given</source>
            <translation>M を決める曲線に沿ったピッチ。M を指定したときは空欄</translation>
        </message>
        <message>
            <source>Height of the ridges the ball leaves between finishing paths</source>
            <translation>仕上げパスの間にボールが残す山の高さ</translation>
        </message>
        <message>
            <source>Roughing allowance</source>
            <translation>荒加工の仕上げ代</translation>
        </message>
        <message>
            <source>Material the Z-level roughing leaves on the surface, along its normal</source>
            <translation>等高線荒加工が曲面に法線方向に残す肉厚</translation>
        </message>
        <message>
            <source>Boundary (paths)</source>
            <translation>境界 (パス)</translation>
        </message>
        <message>
            <source>none: the whole surface</source>
            <translation>なし: 曲面全体</translation>
        </message>
        <message>
            <source>A surface where every path stops: paths of points X, Y, Z, ';' between points, '/' between paths; empty for none</source>
            <translation>各パスが止まる曲面: 点 X, Y, Z のパス。点の間は ';'、パスの間は '/'。なければ空欄</translation>
        </message>
        <message>
            <source>Ball end mill (T)</source>
            <translation>ボールエンドミル (T)</translation>
        </message>
        <message>
            <source>under the smallest concave radius</source>
            <translation>最小凹半径より小さいもの</translation>
        </message>
        <message>
            <source>The ball end mill's number in the tool library; empty: the largest whose radius is under the smallest concave radius</source>
            <translation>工具ライブラリのボールエンドミルの番号。空欄: 半径が最小凹半径より小さい最大のもの</translation>
        </message>
        <message>
            <source>Profile</source>
            <translation>形状</translation>
        </message>
        <message>
            <source>Outer profile (the outside diameter) or inner profile (a bore)</source>
            <translation>外径の輪郭か内径 (穴) の輪郭か</translation>
        </message>
        <message>
            <source>Start X (diameter)</source>
            <translation>始点 X (直径)</translation>
        </message>
        <message>
            <source>Diameter where the profile starts, at its front end</source>
            <translation>輪郭の始点の直径 (前端)</translation>
        </message>
        <message>
            <source>Start Z</source>
            <translation>始点 Z</translation>
        </message>
        <message>
            <source>Z where the profile starts; 0 is the finished front face</source>
            <translation>輪郭の始点の Z；0 は仕上げ後の前端面</translation>
        </message>
    </context>
    <context>
        <name>taiwa::Drawing</name>
        <message>
            <source>AREA – top view</source>
            <translation>AREA – 上面図</translation>
        </message>
        <message>
            <source>Pn</source>
            <translation>Pn</translation>
        </message>
        <message>
            <source>passes</source>
            <translation>パス</translation>
        </message>
        <message>
            <source>section</source>
            <translation>断面</translation>
        </message>
        <message>
            <source>CP – top view</source>
            <translation>CP – 上面図</translation>
        </message>
        <message>
            <source>outline K1, islands K2, K3: CONTOURs</source>
            <translation>外形 K1、島 K2, K3: CONTOUR</translation>
        </message>
        <message>
            <source>FACE – top view</source>
            <translation>FACE – 上面図</translation>
        </message>
        <message>
            <source>margin</source>
            <translation>はみ出し</translation>
        </message>
        <message>
            <source>angle</source>
            <translation>角度</translation>
        </message>
        <message>
            <source>depth</source>
            <translation>深さ</translation>
        </message>
        <message>
            <source>finish</source>
            <translation>仕上げ</translation>
        </message>
        <message>
            <source>HOLES – top view</source>
            <translation>HOLES – 上面図</translation>
        </message>
        <message>
            <source>M2D – top view</source>
            <translation>M2D – 上面図</translation>
        </message>
        <message>
            <source>section along L1</source>
            <translation>L1 方向の断面</translation>
        </message>
        <message>
            <source>M4 – top view</source>
            <translation>M4 – 上面図</translation>
        </message>
        <message>
            <source>X, Y of P1…P4</source>
            <translation>P1…P4 の X, Y</translation>
        </message>
        <message>
            <source>round – top view</source>
            <translation>円形 – 上面図</translation>
        </message>
        <message>
            <source>centre</source>
            <translation>中心</translation>
        </message>
        <message>
            <source>rectangular – top view</source>
            <translation>矩形 – 上面図</translation>
        </message>
        <message>
            <source>-Y (twice)</source>
            <translation>-Y (2 回)</translation>
        </message>
        <message>
            <source>SIDE – top view</source>
            <translation>SIDE – 上面図</translation>
        </message>
        <message>
            <source>climb</source>
            <translation>ダウンカット</translation>
        </message>
        <message>
            <source>side 1: the tool left of K1's direction</source>
            <translation>側 1: 工具は K1 の向きの左</translation>
        </message>
        <message>
            <source>half-section: Z →, X (diameter) ↑</source>
            <translation>半断面: Z →、X (直径) ↑</translation>
        </message>
        <message>
            <source>start X0 Z0</source>
            <translation>始点 X0 Z0</translation>
        </message>
    </context>
</TS>
