<?xml version="1.0" encoding="utf-8"?>
<!-- Texts of the station window (lupdate from ui/ and core/, the module descriptions and the labels of the module drawings, by resources/i18n/update-ts.py, translated by hand); compiled to .qm by lrelease at build time. -->
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
    <context>
        <name>taiwa::ui::DxfImportDialog</name>
        <message>
            <source>Import DXF</source>
            <translation>导入 DXF</translation>
        </message>
        <message>
            <source>No drawing chosen</source>
            <translation>未选择图纸</translation>
        </message>
        <message>
            <source>Choose…</source>
            <translation>选择…</translation>
        </message>
        <message>
            <source>The layers whose lines, arcs, circles, polylines and splines are imported</source>
            <translation>导入其直线、圆弧、圆、多段线和样条的图层</translation>
        </message>
        <message>
            <source>Layers</source>
            <translation>图层</translation>
        </message>
        <message>
            <source>Ends at most this far apart are joined into one contour; wider gaps are reported</source>
            <translation>相距不超过此距离的端点连成一个轮廓；更大的间隙将报告</translation>
        </message>
        <message>
            <source>Gap tolerance</source>
            <translation>间隙容差</translation>
        </message>
        <message>
            <source>What the drawing gives</source>
            <translation>图纸中得到的内容</translation>
        </message>
        <message>
            <source>Figure elements to add</source>
            <translation>要添加的图形元素</translation>
        </message>
        <message>
            <source>Import</source>
            <translation>导入</translation>
        </message>
        <message>
            <source>DXF drawings (*.dxf *.DXF)</source>
            <translation>DXF 图纸 (*.dxf *.DXF)</translation>
        </message>
        <message>
            <source>%1 entities</source>
            <translation>%1 个实体</translation>
        </message>
        <message>
            <source>Refused: %1</source>
            <translation>无法导入: %1</translation>
        </message>
        <message>
            <source>No layer is ticked.</source>
            <translation>未勾选任何图层。</translation>
        </message>
        <message>
            <source>%1 closed and %2 open contours, drawn in %3.</source>
            <translation>闭合轮廓 %1 个，开放轮廓 %2 个（图纸单位 %3）。</translation>
        </message>
        <message>
            <source>%1 ends joined over gaps within the tolerance; the largest %2 mm.</source>
            <translation>在容差内连接了 %1 处端点间隙；最大 %2 mm。</translation>
        </message>
        <message>
            <source>Gap: %1</source>
            <translation>间隙: %1</translation>
        </message>
        <message>
            <source>Branch: %1</source>
            <translation>分支: %1</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::ExportDialog</name>
        <message>
            <source>Export tape and sheet</source>
            <translation>导出程序和作业指导书</translation>
        </message>
        <message>
            <source>the folder the files are written into</source>
            <translation>写入文件的文件夹</translation>
        </message>
        <message>
            <source>Choose…</source>
            <translation>选择…</translation>
        </message>
        <message>
            <source>Folder</source>
            <translation>文件夹</translation>
        </message>
        <message>
            <source>Controller dialect</source>
            <translation>NC 格式 (控制器)</translation>
        </message>
        <message>
            <source>The job's own</source>
            <translation>作业本身的单位</translation>
        </message>
        <message>
            <source>Millimetres</source>
            <translation>毫米</translation>
        </message>
        <message>
            <source>Inches</source>
            <translation>英寸</translation>
        </message>
        <message>
            <source>Units</source>
            <translation>单位</translation>
        </message>
        <message>
            <source>The sheet shows the setup and every step in a picture</source>
            <translation>作业指导书附装夹图和每个工步的图</translation>
        </message>
        <message>
            <source>Pictures</source>
            <translation>图</translation>
        </message>
        <message>
            <source>The grid the verification cuts the steps into before the files are written: finer finds smaller gouges and takes longer.</source>
            <translation>导出前验证切削各工步所用的网格: 越细越能发现小的过切, 也越费时。</translation>
        </message>
        <message>
            <source>Verification grid</source>
            <translation>验证网格</translation>
        </message>
        <message>
            <source>Export</source>
            <translation>导出</translation>
        </message>
        <message>
            <source>Export into folder</source>
            <translation>导出到文件夹</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::FigurePanel</name>
        <message>
            <source>The figure's contours have no chamfer.</source>
            <translation>图形的轮廓中没有倒角。</translation>
        </message>
        <message>
            <source>The figure's contours have no rounding.</source>
            <translation>图形的轮廓中没有圆角。</translation>
        </message>
        <message>
            <source>Click a chamfer in the view to change it (%1 in the figure).</source>
            <translation>在视图中单击要修改的倒角（图形中共 %1 个）。</translation>
        </message>
        <message>
            <source>Click a rounding in the view to change it (%1 in the figure).</source>
            <translation>在视图中单击要修改的圆角（图形中共 %1 个）。</translation>
        </message>
        <message>
            <source>%1: chamfer between %2 and %3, length</source>
            <translation>%1：%2 与 %3 之间的倒角，长度</translation>
        </message>
        <message>
            <source>%1: rounding between %2 and %3, radius</source>
            <translation>%1：%2 与 %3 之间的圆角，半径</translation>
        </message>
        <message>
            <source>The text has a refusal: correct it before revising a corner.</source>
            <translation>文本有错误：请先更正，再修改拐角。</translation>
        </message>
        <message>
            <source>Revise corner %1 of %2</source>
            <translation>修改 %2 的拐角 %1</translation>
        </message>
        <message>
            <source>Figure elements, one statement a line</source>
            <translation>图形元素（每行一条语句）</translation>
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
            <translation>文本中被拒绝之处；单击可跳到其位置</translation>
        </message>
        <message>
            <source>Revise chamfer</source>
            <translation>修改倒角</translation>
        </message>
        <message>
            <source>Revise rounding</source>
            <translation>修改圆角</translation>
        </message>
        <message>
            <source>Fit</source>
            <translation>适合窗口</translation>
        </message>
        <message>
            <source>Frame the stock, the points and the contours</source>
            <translation>显示毛坯、点和轮廓的全部</translation>
        </message>
        <message>
            <source>Edit figure</source>
            <translation>编辑图形</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::FigureView</name>
        <message>
            <source>Click: pick an element. Wheel: zoom. Drag: pan. Double click: fit.</source>
            <translation>单击：选取元素。滚轮：缩放。拖动：平移。双击：适合窗口。</translation>
        </message>
        <message>
            <source>Click: the next point of the passes. Wheel: zoom. Drag: pan. Double click: fit.</source>
            <translation>单击：路径的下一个点。滚轮：缩放。拖动：平移。双击：适应窗口。</translation>
        </message>
        <message>
            <source>Drawing passes: click the start, then the end of each pass; wheel: zoom, drag: pan</source>
            <translation>绘制路径：先单击起点，再单击每条路径的终点；滚轮：缩放，拖动：平移</translation>
        </message>
        <message>
            <source>X →  Y ↑   wheel: zoom, drag: pan, double click: fit</source>
            <translation>X →  Y ↑   滚轮：缩放，拖动：平移，双击：适合窗口</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::FileActions</name>
        <message>
            <source>%1 (shop server)</source>
            <translation>%1（车间服务器）</translation>
        </message>
        <message>
            <source>untitled</source>
            <translation>未命名</translation>
        </message>
        <message>
            <source>Unsaved changes</source>
            <translation>未保存的更改</translation>
        </message>
        <message>
            <source>The job has unsaved changes. Save them?</source>
            <translation>作业有未保存的更改。要保存吗?</translation>
        </message>
        <message>
            <source>New job</source>
            <translation>新建作业</translation>
        </message>
        <message>
            <source>Open job</source>
            <translation>打开作业</translation>
        </message>
        <message>
            <source>Import a turned part (STEP)</source>
            <translation>导入车削零件 (STEP)</translation>
        </message>
        <message>
            <source>STEP models (*.step *.stp *.STEP *.STP)</source>
            <translation>STEP 模型 (*.step *.stp *.STEP *.STP)</translation>
        </message>
        <message>
            <source>Cannot import</source>
            <translation>无法导入</translation>
        </message>
        <message numerus="yes">
            <source>Imported %1: %n turned profile(s)</source>
            <translation>
                <numerusform>已导入 %1:%n 个车削轮廓</numerusform>
            </translation>
        </message>
        <message>
            <source>Import a surface (STEP face set)</source>
            <translation>导入曲面（STEP 面集）</translation>
        </message>
        <message>
            <source>Imported %1 as a surface: moved %2 mm in Z to put its top at Z 0; the paths stay within %3 µm of its faces</source>
            <translation>已将 %1 作为曲面导入: 沿 Z 移动 %2 mm 使其顶点位于 Z 0；路径与面的偏差在 %3 µm 以内</translation>
        </message>
        <message>
            <source>Cannot open job</source>
            <translation>无法打开作业</translation>
        </message>
        <message>
            <source>Opened %1</source>
            <translation>已打开 %1</translation>
        </message>
        <message>
            <source>Save job</source>
            <translation>保存作业</translation>
        </message>
        <message>
            <source>%1 was changed on disk since this window opened or saved it (by another window or program).</source>
            <translation>自本窗口打开或保存 %1 以来,它已在磁盘上被(其他窗口或程序)修改。</translation>
        </message>
        <message>
            <source> Not saved: use Save As.</source>
            <translation> 未保存:请使用“另存为”。</translation>
        </message>
        <message>
            <source> Overwrite it with this window's job?</source>
            <translation> 用本窗口的作业覆盖它吗?</translation>
        </message>
        <message>
            <source>Cannot save job</source>
            <translation>无法保存作业</translation>
        </message>
        <message>
            <source>Saved %1</source>
            <translation>已保存 %1</translation>
        </message>
        <message>
            <source>Export</source>
            <translation>导出</translation>
        </message>
        <message>
            <source>The job has input errors; fix them before exporting.</source>
            <translation>作业有输入错误,请在导出前修正。</translation>
        </message>
        <message>
            <source>Export failed</source>
            <translation>导出失败</translation>
        </message>
        <message numerus="yes">
            <source>The verification found %n faults (the first: %1).</source>
            <translation>
                <numerusform>验证发现 %n 个错误 (第一个: %1)。</numerusform>
            </translation>
        </message>
        <message>
            <source>Write the files anyway, with the faults on the sheet?</source>
            <translation>仍然写入文件, 并在作业指导书上注明这些错误吗?</translation>
        </message>
        <message>
            <source>Exported %1 files into %2</source>
            <translation>已将 %1 个文件导出到 %2</translation>
        </message>
        <message>
            <source>(pictures missing: %1)</source>
            <translation>(缺少图: %1)</translation>
        </message>
        <message>
            <source>an untitled job</source>
            <translation>未命名作业</translation>
        </message>
        <message>
            <source>Recover job</source>
            <translation>恢复作业</translation>
        </message>
        <message>
            <source>Taiwa was not closed properly while editing %1. Its autosaved copy is newer than the file. Restore the autosaved copy?</source>
            <translation>编辑 %1 时 Taiwa 未正常关闭。自动保存的副本比文件更新。要恢复自动保存的副本吗?</translation>
        </message>
        <message>
            <source>Restored the autosaved job (not saved to a file yet)</source>
            <translation>已恢复自动保存的作业(尚未保存到文件)</translation>
        </message>
        <message>
            <source>(none)</source>
            <translation>(无)</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::JobProperties</name>
        <message>
            <source>Name</source>
            <translation>名称</translation>
        </message>
        <message>
            <source>Material</source>
            <translation>材料</translation>
        </message>
        <message>
            <source>Units</source>
            <translation>单位</translation>
        </message>
        <message>
            <source>Machine</source>
            <translation>机床</translation>
        </message>
        <message>
            <source>Clamping</source>
            <translation>装夹</translation>
        </message>
        <message>
            <source>Jaws' height</source>
            <translation>钳口高度</translation>
        </message>
        <message>
            <source>mm</source>
            <translation>mm</translation>
        </message>
        <message>
            <source>inch (converts every length)</source>
            <translation>英寸(换算所有长度)</translation>
        </message>
        <message>
            <source>not given</source>
            <translation>未指定</translation>
        </message>
        <message>
            <source>vice on the X faces</source>
            <translation>虎钳夹持 X 面</translation>
        </message>
        <message>
            <source>vice on the Y faces</source>
            <translation>虎钳夹持 Y 面</translation>
        </message>
        <message>
            <source>How the block is held, for the instruction sheet's setup picture</source>
            <translation>毛坯的装夹方式（用于工艺卡的装夹图）</translation>
        </message>
        <message>
            <source>How far up the block's sides the jaws grip, from its bottom</source>
            <translation>钳口夹持毛坯侧面的高度（自底面起）</translation>
        </message>
        <message>
            <source>Machine %1</source>
            <translation>机床 %1</translation>
        </message>
        <message>
            <source>Change clamping</source>
            <translation>更改装夹</translation>
        </message>
        <message>
            <source>Edit job name</source>
            <translation>编辑作业名称</translation>
        </message>
        <message>
            <source>Change material</source>
            <translation>更改材料</translation>
        </message>
        <message>
            <source>Change length unit</source>
            <translation>更改长度单位</translation>
        </message>
        <message>
            <source>not a number</source>
            <translation>不是数字</translation>
        </message>
        <message>
            <source>Edit %1</source>
            <translation>编辑 %1</translation>
        </message>
        <message>
            <source> (unknown)</source>
            <translation>(未知)</translation>
        </message>
        <message>
            <source>Stock width (X)</source>
            <translation>毛坯宽度 (X)</translation>
        </message>
        <message>
            <source>Stock length (Y)</source>
            <translation>毛坯长度 (Y)</translation>
        </message>
        <message>
            <source>Stock height (Z)</source>
            <translation>毛坯高度 (Z)</translation>
        </message>
        <message>
            <source>Bar diameter</source>
            <translation>棒料直径</translation>
        </message>
        <message>
            <source>Bar length</source>
            <translation>棒料长度</translation>
        </message>
        <message>
            <source>Face stock</source>
            <translation>端面余量</translation>
        </message>
        <message>
            <source>Bore (0: solid)</source>
            <translation>内孔直径 (0:实心)</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::NcView</name>
        <message>
            <source>&amp;NC dialect:</source>
            <translation>数控系统(&amp;N):</translation>
        </message>
        <message numerus="yes">
            <source>%n block(s)</source>
            <translation>
                <numerusform>%n 个程序段</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::PassesBar</name>
        <message>
            <source>Remove the last point of the passes</source>
            <translation>删除路径的最后一点</translation>
        </message>
        <message>
            <source>Clear the passes</source>
            <translation>清除路径</translation>
        </message>
        <message>
            <source>Draw passes</source>
            <translation>绘制路径</translation>
        </message>
        <message>
            <source>Click in the view: the first point is where the tool starts, each next one ends a pass</source>
            <translation>在视图中单击：第一个点为刀具起点，之后每个点为一条路径的终点</translation>
        </message>
        <message>
            <source>Remove last point</source>
            <translation>删除最后一点</translation>
        </message>
        <message>
            <source>Take back the last point drawn</source>
            <translation>撤回最后绘制的点</translation>
        </message>
        <message>
            <source>Clear</source>
            <translation>清除</translation>
        </message>
        <message>
            <source>Remove every pass of this unit</source>
            <translation>删除此单元的所有路径</translation>
        </message>
        <message>
            <source>Draw the start point of the passes</source>
            <translation>绘制路径起点</translation>
        </message>
        <message>
            <source>Draw a pass</source>
            <translation>绘制一条路径</translation>
        </message>
        <message>
            <source>No pass drawn: press Draw passes and click where the tool starts.</source>
            <translation>尚未绘制路径：按“绘制路径”并单击刀具起点。</translation>
        </message>
        <message>
            <source>The start point is drawn: click where the first pass ends.</source>
            <translation>已绘制起点：请单击第一条路径的终点。</translation>
        </message>
        <message>
            <source>1 pass drawn.</source>
            <translation>已绘制 1 条路径。</translation>
        </message>
        <message>
            <source>%1 passes drawn.</source>
            <translation>已绘制 %1 条路径。</translation>
        </message>
        <message>
            <source>The area %1 is not a closed contour of the figure.</source>
            <translation>区域 %1 不是图形中的闭合轮廓。</translation>
        </message>
        <message>
            <source>The start point is too near the walls.</source>
            <translation>起点离壁太近。</translation>
        </message>
        <message>
            <source>Pass %1 leaves the area.</source>
            <translation>路径 %1 超出区域。</translation>
        </message>
        <message>
            <source>The strips sweep the whole area.</source>
            <translation>条带覆盖整个区域。</translation>
        </message>
        <message>
            <source>Unswept: %1 in one place.</source>
            <translation>未切削：1 处，共 %1。</translation>
        </message>
        <message>
            <source>Unswept: %1 in %2 places.</source>
            <translation>未切削：%2 处，共 %1。</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::PlanRunner</name>
        <message>
            <source>%1 changed by %2 at station %3; the plan is run again</source>
            <translation>%1 已由 %2 在工位 %3 更改；重新运行计划</translation>
        </message>
        <message>
            <source>(no program: the job has input errors)</source>
            <translation>(无程序:作业有输入错误)</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::ProfileEditor</name>
        <message>
            <source>Edge</source>
            <translation>边</translation>
        </message>
        <message>
            <source>Element</source>
            <translation>元素</translation>
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
            <translation>圆心 X</translation>
        </message>
        <message>
            <source>Centre Z</source>
            <translation>圆心 Z</translation>
        </message>
        <message>
            <source>Corner</source>
            <translation>拐角</translation>
        </message>
        <message>
            <source>Size</source>
            <translation>尺寸</translation>
        </message>
        <message>
            <source>Ra µm</source>
            <translation>Ra µm</translation>
        </message>
        <message>
            <source>Tolerance</source>
            <translation>公差</translation>
        </message>
        <message>
            <source>Thread pitch</source>
            <translation>螺距</translation>
        </message>
        <message>
            <source>Allowance</source>
            <translation>磨削余量</translation>
        </message>
        <message>
            <source>Adjustment</source>
            <translation>调整量</translation>
        </message>
        <message>
            <source>Relief groove</source>
            <translation>退刀槽</translation>
        </message>
        <message>
            <source>Width</source>
            <translation>宽度</translation>
        </message>
        <message>
            <source>Depth</source>
            <translation>深度</translation>
        </message>
        <message>
            <source>line</source>
            <translation>直线</translation>
        </message>
        <message>
            <source>arc CW (G2)</source>
            <translation>顺时针圆弧 (G2)</translation>
        </message>
        <message>
            <source>arc CCW (G3)</source>
            <translation>逆时针圆弧 (G3)</translation>
        </message>
        <message>
            <source>none</source>
            <translation>无</translation>
        </message>
        <message>
            <source>chamfer</source>
            <translation>倒角</translation>
        </message>
        <message>
            <source>rounding</source>
            <translation>圆角</translation>
        </message>
        <message>
            <source>Allowances and grooves drawn ×%1</source>
            <translation>磨削余量和退刀槽按 ×%1 显示</translation>
        </message>
        <message>
            <source>Profile, in cutting order (X is a diameter; arcs: R, or the centre)</source>
            <translation>轮廓,按切削顺序(X 为直径;圆弧:R 或圆心)</translation>
        </message>
        <message>
            <source>Grinding allowance per edge (empty: adjustment from the finishing tool's nose radius, depth = allowance, no width = no groove)</source>
            <translation>各边的磨削余量(空:调整量取精加工刀具的刀尖圆弧半径,深度 = 余量,无宽度 = 无槽)</translation>
        </message>
        <message>
            <source>Add row</source>
            <translation>添加行</translation>
        </message>
        <message>
            <source>Insert row</source>
            <translation>插入行</translation>
        </message>
        <message>
            <source>Delete row</source>
            <translation>删除行</translation>
        </message>
        <message>
            <source>Revise chamfers</source>
            <translation>修改倒角</translation>
        </message>
        <message>
            <source>Revise roundings</source>
            <translation>修改圆角</translation>
        </message>
        <message>
            <source>Done</source>
            <translation>完成</translation>
        </message>
        <message>
            <source>Add allowance for picked edge</source>
            <translation>为所选边添加余量</translation>
        </message>
        <message>
            <source>Delete allowance</source>
            <translation>删除余量</translation>
        </message>
        <message>
            <source>Element of row %1</source>
            <translation>第 %1 行的元素</translation>
        </message>
        <message>
            <source>Corner of row %1</source>
            <translation>第 %1 行的拐角</translation>
        </message>
        <message>
            <source>Groove kind of allowance %1</source>
            <translation>余量 %1 的槽类型</translation>
        </message>
        <message>
            <source>profile row %1, %2</source>
            <translation>轮廓第 %1 行，%2</translation>
        </message>
        <message>
            <source>allowance row %1, %2</source>
            <translation>磨削余量第 %1 行，%2</translation>
        </message>
        <message>
            <source>not a number</source>
            <translation>不是数字</translation>
        </message>
        <message>
            <source>row %1: not a number</source>
            <translation>第 %1 行:不是数字</translation>
        </message>
        <message>
            <source>%1 of row %2</source>
            <translation>第 %2 行的 %1</translation>
        </message>
        <message>
            <source>allowance %1: not a number</source>
            <translation>余量 %1:不是数字</translation>
        </message>
        <message>
            <source>%1 of allowance %2</source>
            <translation>余量 %2 的 %1</translation>
        </message>
        <message>
            <source>Add row %1</source>
            <translation>添加第 %1 行</translation>
        </message>
        <message>
            <source>Delete row %1</source>
            <translation>删除第 %1 行</translation>
        </message>
        <message>
            <source>Pick an edge in the view first.</source>
            <translation>请先在图中选择一条边。</translation>
        </message>
        <message>
            <source>%1 has an allowance already.</source>
            <translation>%1 已有余量。</translation>
        </message>
        <message>
            <source>Add grinding allowance for %1</source>
            <translation>为 %1 添加磨削余量</translation>
        </message>
        <message>
            <source>Delete allowance %1</source>
            <translation>删除余量 %1</translation>
        </message>
        <message>
            <source>Chamfer %1: leg</source>
            <translation>倒角 %1:边长</translation>
        </message>
        <message>
            <source>Rounding %1: radius</source>
            <translation>圆角 %1:半径</translation>
        </message>
        <message>
            <source>chamfers</source>
            <translation>倒角</translation>
        </message>
        <message>
            <source>roundings</source>
            <translation>圆角</translation>
        </message>
        <message>
            <source>The profile has no %1.</source>
            <translation>轮廓中没有%1。</translation>
        </message>
        <message>
            <source>%1 %2: pick one in the view</source>
            <translation>%1 个%2:请在图中选择一个</translation>
        </message>
        <message>
            <source>Revise %1</source>
            <translation>修改 %1</translation>
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
            <translation>- - - 待切削(含磨削余量)</translation>
        </message>
        <message>
            <source>- - - to cut (grinding allowance, its depth drawn ×%1)</source>
            <translation>- - - 待切削(含磨削余量,深度按 ×%1 显示)</translation>
        </message>
    </context>
    <context>
        <name>QObject</name>
        <message>
            <source>(no program: the job has input errors)</source>
            <translation>(无程序:作业有输入错误)</translation>
        </message>
        <message>
            <source>(no program: %1)</source>
            <translation>(无程序:%1)</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::SectionBar</name>
        <message>
            <source>No section</source>
            <translation>无剖面</translation>
        </message>
        <message>
            <source>Section across X</source>
            <translation>X 向剖面</translation>
        </message>
        <message>
            <source>Section across Y</source>
            <translation>Y 向剖面</translation>
        </message>
        <message>
            <source>Section across Z</source>
            <translation>Z 向剖面</translation>
        </message>
        <message>
            <source>Cut the stock open along a plane to see inside it</source>
            <translation>用平面剖开毛坯查看内部</translation>
        </message>
        <message>
            <source>Where the plane cuts the stock</source>
            <translation>平面剖切毛坯的位置</translation>
        </message>
        <message>
            <source>A plane across X or Y turned about Z</source>
            <translation>X 或 Y 向平面绕 Z 轴转过的角度</translation>
        </message>
        <message>
            <source>Flip</source>
            <translation>翻转</translation>
        </message>
        <message>
            <source>Take away the material on the other side of the plane</source>
            <translation>去掉平面另一侧的材料</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::StationWindow</name>
        <message>
            <source>Modules</source>
            <translation>模块</translation>
        </message>
        <message>
            <source>Machining units, in order</source>
            <translation>加工单元(按顺序)</translation>
        </message>
        <message>
            <source>Job</source>
            <translation>作业</translation>
        </message>
        <message>
            <source>Unit</source>
            <translation>单元</translation>
        </message>
        <message>
            <source>Technology data…</source>
            <translation>工艺数据…</translation>
        </message>
        <message>
            <source>Tool library…</source>
            <translation>刀具库…</translation>
        </message>
        <message>
            <source>Pick a module on the left to add a machining unit.</source>
            <translation>在左侧选择一个模块以添加加工单元。</translation>
        </message>
        <message>
            <source>No 3-D preview: this display has no OpenGL.</source>
            <translation>无 3D 预览:此显示器不支持 OpenGL。</translation>
        </message>
        <message>
            <source>3-D view</source>
            <translation>3D 视图</translation>
        </message>
        <message>
            <source>Figure</source>
            <translation>图形</translation>
        </message>
        <message>
            <source>Steps</source>
            <translation>工步</translation>
        </message>
        <message>
            <source>Steps by path</source>
            <translation>按系统的工步</translation>
        </message>
        <message>
            <source>Path 1</source>
            <translation>系统 1</translation>
        </message>
        <message>
            <source>Path 2</source>
            <translation>系统 2</translation>
        </message>
        <message>
            <source>&amp;File</source>
            <translation>文件(&amp;F)</translation>
        </message>
        <message>
            <source>&amp;New</source>
            <translation>新建(&amp;N)</translation>
        </message>
        <message>
            <source>&amp;Open…</source>
            <translation>打开(&amp;O)…</translation>
        </message>
        <message>
            <source>Open &amp;recent</source>
            <translation>最近打开(&amp;R)</translation>
        </message>
        <message>
            <source>&amp;Import turned part (STEP)…</source>
            <translation>导入车削零件 (STEP)(&amp;I)…</translation>
        </message>
        <message>
            <source>Import s&amp;urface (STEP face set)…</source>
            <translation>导入曲面（STEP 面集）(&amp;U)…</translation>
        </message>
        <message>
            <source>Import &amp;DXF contours…</source>
            <translation>导入 DXF 轮廓(&amp;D)…</translation>
        </message>
        <message>
            <source>&amp;Save</source>
            <translation>保存(&amp;S)</translation>
        </message>
        <message>
            <source>Save &amp;as…</source>
            <translation>另存为(&amp;A)…</translation>
        </message>
        <message>
            <source>Open from the s&amp;hop server…</source>
            <translation>从车间服务器打开(&amp;H)…</translation>
        </message>
        <message>
            <source>Save to the shop ser&amp;ver</source>
            <translation>保存到车间服务器(&amp;V)</translation>
        </message>
        <message>
            <source>&amp;Export tape and sheet…</source>
            <translation>导出程序和作业指导书(&amp;E)…</translation>
        </message>
        <message>
            <source>Ctrl+E</source>
            <translation>Ctrl+E</translation>
        </message>
        <message>
            <source>&amp;Quit</source>
            <translation>退出(&amp;Q)</translation>
        </message>
        <message>
            <source>&amp;Edit</source>
            <translation>编辑(&amp;E)</translation>
        </message>
        <message>
            <source>&amp;Undo</source>
            <translation>撤销(&amp;U)</translation>
        </message>
        <message>
            <source>&amp;Redo</source>
            <translation>重做(&amp;R)</translation>
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
            <translation>作业(&amp;J)</translation>
        </message>
        <message>
            <source>&amp;Technology data…</source>
            <translation>工艺数据(&amp;T)…</translation>
        </message>
        <message>
            <source>Ctrl+T</source>
            <translation>Ctrl+T</translation>
        </message>
        <message>
            <source>Tool &amp;library…</source>
            <translation>刀具库(&amp;L)…</translation>
        </message>
        <message>
            <source>Ctrl+L</source>
            <translation>Ctrl+L</translation>
        </message>
        <message>
            <source>&amp;View</source>
            <translation>视图(&amp;V)</translation>
        </message>
        <message>
            <source>Tool &amp;paths</source>
            <translation>刀具路径(&amp;P)</translation>
        </message>
        <message>
            <source>&amp;Stock as cut</source>
            <translation>切削后的毛坯(&amp;S)</translation>
        </message>
        <message>
            <source>Pa&amp;rt</source>
            <translation>零件(&amp;R)</translation>
        </message>
        <message>
            <source>The finished pockets' outlines, or the turned part</source>
            <translation>完成的型腔轮廓,或车削零件</translation>
        </message>
        <message>
            <source>&amp;Zoom to the selected step</source>
            <translation>缩放到所选工步(&amp;Z)</translation>
        </message>
        <message>
            <source>&amp;Language</source>
            <translation>语言(&amp;L)</translation>
        </message>
        <message>
            <source>No translation for %1: English is shown.</source>
            <translation>没有%1的翻译：以英文显示。</translation>
        </message>
        <message>
            <source>Stock &amp;grid</source>
            <translation>毛坯网格(&amp;G)</translation>
        </message>
        <message>
            <source>Fine: %1 mm, up to %2 cells</source>
            <translation>细:%1 mm,最多 %2 个单元格</translation>
        </message>
        <message>
            <source>Standard: %1 mm, up to %2 cells</source>
            <translation>标准:%1 mm,最多 %2 个单元格</translation>
        </message>
        <message>
            <source>Coarse: %1 mm, up to %2 cells</source>
            <translation>粗:%1 mm,最多 %2 个单元格</translation>
        </message>
        <message>
            <source>Stock grid: %1 mm cells on this stock</source>
            <translation>毛坯网格:此毛坯上为 %1 mm 单元格</translation>
        </message>
        <message>
            <source>Tool library: %1 (using the built-in library)</source>
            <translation>刀具库:%1(使用内置刀具库)</translation>
        </message>
        <message>
            <source>DXF contours become figure elements, which a lathe job does not use.</source>
            <translation>DXF 轮廓会成为图形元素，而车削作业不使用图形元素。</translation>
        </message>
        <message>
            <source>Import DXF contours</source>
            <translation>导入 DXF 轮廓</translation>
        </message>
        <message>
            <source>Edit %1 of unit %2</source>
            <translation>编辑单元 %2 的 %1</translation>
        </message>
        <message>
            <source>Not up to date: the job has input errors. The 3-D view and the NC program show the last valid job. First error: %1</source>
            <translation>不是最新:作业有输入错误。3D 视图和 NC 程序显示的是最后一个有效作业。第一个错误:%1</translation>
        </message>
        <message>
            <source>job</source>
            <translation>作业</translation>
        </message>
        <message numerus="yes">
            <source>%n problem(s) in other units</source>
            <translation>
                <numerusform>其他单元中有 %n 个问题</numerusform>
            </translation>
        </message>
        <message>
            <source>Edit technology data</source>
            <translation>编辑工艺数据</translation>
        </message>
        <message numerus="yes">
            <source>%1 is also open in %n other window(s): a save here asks before it overwrites what another window saved.</source>
            <translation>
                <numerusform>%1 也在其他 %n 个窗口中打开:在此保存时,覆盖其他窗口保存的内容前会先询问。</numerusform>
            </translation>
        </message>
        <message>
            <source>%1 of unit %2</source>
            <translation>单元 %2 的 %1</translation>
        </message>
        <message>
            <source>Rename unit %1</source>
            <translation>重命名单元 %1</translation>
        </message>
        <message>
            <source>Dialect %1</source>
            <translation>数控系统格式 %1</translation>
        </message>
        <message>
            <source>Spindle speed of %1, unit %2</source>
            <translation>%1 的主轴转速（单元 %2）</translation>
        </message>
        <message>
            <source>Feed of %1, unit %2</source>
            <translation>%1 的进给（单元 %2）</translation>
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
            <translation>▶ 播放(&amp;Y)</translation>
        </message>
        <message>
            <source>&amp;Stock</source>
            <translation>毛坯(&amp;S)</translation>
        </message>
        <message>
            <source>The stock as the simulation cuts it, instead of a glass block</source>
            <translation>显示仿真切削后的毛坯,而不是玻璃块</translation>
        </message>
        <message>
            <source>&amp;Before step</source>
            <translation>工步之前(&amp;B)</translation>
        </message>
        <message>
            <source>The stock as it is before the selected step, instead of after it</source>
            <translation>显示所选工步之前而不是之后的毛坯</translation>
        </message>
        <message>
            <source>&amp;All steps</source>
            <translation>全部工步(&amp;A)</translation>
        </message>
        <message>
            <source>&amp;Iso</source>
            <translation>轴测(&amp;I)</translation>
        </message>
        <message>
            <source>&amp;Top</source>
            <translation>俯视(&amp;T)</translation>
        </message>
        <message>
            <source>F&amp;ront</source>
            <translation>正视(&amp;R)</translation>
        </message>
        <message>
            <source>&amp;Zoom to step</source>
            <translation>缩放到工步(&amp;Z)</translation>
        </message>
        <message>
            <source>Zoom to the selected step, the view turned as it is (all steps: the whole job)</source>
            <translation>缩放到所选工步,视角方向不变(全部工步:整个作业)</translation>
        </message>
        <message>
            <source>Pat&amp;hs</source>
            <translation>刀具路径(&amp;H)</translation>
        </message>
        <message>
            <source>The tool paths drawn; off, the stock and the colour map show unhidden</source>
            <translation>显示刀具路径;关闭后毛坯和色图不再被路径遮挡</translation>
        </message>
        <message>
            <source>One block back in the selected step</source>
            <translation>在所选工步中后退一个程序段</translation>
        </message>
        <message>
            <source>One block on in the selected step, the material coming off</source>
            <translation>在所选工步中前进一个程序段（显示材料被切除）</translation>
        </message>
        <message>
            <source>How many blocks Play moves on ten times a second with a step selected</source>
            <translation>选中工步播放时，每秒十次各前进的程序段数</translation>
        </message>
        <message>
            <source>No steps: the job has input errors.</source>
            <translation>无工步:作业有输入错误。</translation>
        </message>
        <message numerus="yes">
            <source>%n step(s), %1 min, %2 tool change(s) (updating…)</source>
            <translation>
                <numerusform>%n 个工步,%1 分钟,换刀 %2 次(更新中…)</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n step(s), %1 min, %2 tool change(s)</source>
            <translation>
                <numerusform>%n 个工步,%1 分钟,换刀 %2 次</numerusform>
            </translation>
        </message>
        <message>
            <source>&lt;b&gt;%1&lt;/b&gt; of unit %2 (%3), machining type %4</source>
            <translation>单元 %2 (%3) 的 &lt;b&gt;%1&lt;/b&gt;,加工类型 %4</translation>
        </message>
        <message>
            <source>Air to %1, cuts to %2; leaves wall %3, floor %4</source>
            <translation>空走至 %1,切削至 %2;侧壁余量 %3,底面余量 %4</translation>
        </message>
        <message>
            <source>Outline %1, r %2</source>
            <translation>轮廓 %1,r %2</translation>
        </message>
        <message>
            <source>Inclined face at %1° from the vertical, scallop %2</source>
            <translation>斜面与竖直方向成 %1°,残留高度 %2</translation>
        </message>
        <message>
            <source>At (%1, %2), Ø %3</source>
            <translation>位置 (%1, %2),Ø %3</translation>
        </message>
        <message>
            <source>Wall taper %1° per side</source>
            <translation>侧壁单边斜度 %1°</translation>
        </message>
        <message>
            <source>T%1 %2: %3</source>
            <translation>T%1 %2:%3</translation>
        </message>
        <message>
            <source>Estimated %1 min (%2 min as the machine moves)</source>
            <translation>估计 %1 分钟（按机床运动 %2 分钟）</translation>
        </message>
        <message>
            <source>Estimated %1 min</source>
            <translation>预计 %1 分钟</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::StepTable</name>
        <message>
            <source>No.</source>
            <translation>序号</translation>
        </message>
        <message>
            <source>Unit</source>
            <translation>单元</translation>
        </message>
        <message>
            <source>Step</source>
            <translation>工步</translation>
        </message>
        <message>
            <source>Tool</source>
            <translation>刀具</translation>
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
            <translation>起始深度</translation>
        </message>
        <message>
            <source>Depth</source>
            <translation>深度</translation>
        </message>
        <message>
            <source>Time</source>
            <translation>时间</translation>
        </message>
        <message>
            <source>Spindle speed (rpm; m/min under constant surface speed): type to set it for this unit's steps of this kind, empty it for the tool's</source>
            <translation>主轴转速（r/min；恒线速时为 m/min）：输入即为本单元此类工步设定，清空则恢复刀具的切削参数</translation>
        </message>
        <message>
            <source>Feed (per minute; per revolution on a lathe): type to set it for this unit's steps of this kind, empty it for the tool's</source>
            <translation>进给（每分钟；车床为每转）：输入即为本单元此类工步设定，清空则恢复刀具的切削参数</translation>
        </message>
        <message>
            <source>Set for this step kind of the unit; empty the cell for the tool's cutting data</source>
            <translation>为本单元此类工步设定的值；清空则恢复刀具的切削参数</translation>
        </message>
        <message>
            <source>Depth of cut on the radius: of a pass; of a thread, the whole thread</source>
            <translation>半径方向的切深：每刀的；螺纹为整个螺纹的深度</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::StoreActions</name>
        <message>
            <source>Shop server</source>
            <translation>车间服务器</translation>
        </message>
        <message>
            <source>The job store needs the shop server: TAIWA_TOOL_DB names the file %1, not a server</source>
            <translation>作业库需要车间服务器：TAIWA_TOOL_DB 指向的是文件 %1，而不是服务器</translation>
        </message>
        <message>
            <source>Open from the shop server</source>
            <translation>从车间服务器打开</translation>
        </message>
        <message>
            <source>The shop server holds no jobs yet</source>
            <translation>车间服务器上还没有作业</translation>
        </message>
        <message>
            <source>Job:</source>
            <translation>作业：</translation>
        </message>
        <message>
            <source>Cannot open job</source>
            <translation>无法打开作业</translation>
        </message>
        <message>
            <source>Opened %1 from the shop server (version %2); this station holds its lock</source>
            <translation>已从车间服务器打开 %1（版本 %2）；本工位持有其锁</translation>
        </message>
        <message>
            <source>Save to the shop server</source>
            <translation>保存到车间服务器</translation>
        </message>
        <message>
            <source>Name in the job store:</source>
            <translation>在作业库中的名称：</translation>
        </message>
        <message>
            <source>Cannot save job</source>
            <translation>无法保存作业</translation>
        </message>
        <message>
            <source>Saved %1 to the shop server as version %2</source>
            <translation>已将 %1 作为版本 %2 保存到车间服务器</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::TechnologyDialog</name>
        <message>
            <source>Technology data</source>
            <translation>工艺数据</translation>
        </message>
        <message>
            <source>&lt;b&gt;Value&lt;/b&gt;</source>
            <translation>&lt;b&gt;项目&lt;/b&gt;</translation>
        </message>
        <message>
            <source>&lt;b&gt;Table (%1)&lt;/b&gt;</source>
            <translation>&lt;b&gt;数据表 (%1)&lt;/b&gt;</translation>
        </message>
        <message>
            <source>&lt;b&gt;This job&lt;/b&gt; (empty = table)</source>
            <translation>&lt;b&gt;本作业&lt;/b&gt;(空 = 数据表)</translation>
        </message>
        <message>
            <source>&lt;b&gt;In force&lt;/b&gt;</source>
            <translation>&lt;b&gt;生效值&lt;/b&gt;</translation>
        </message>
        <message>
            <source>(unknown material)</source>
            <translation>(未知材料)</translation>
        </message>
        <message>
            <source>not a number</source>
            <translation>不是数字</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::ToolLibraryDialog</name>
        <message>
            <source>&amp;Reset wear</source>
            <translation>重置磨损(&amp;R)</translation>
        </message>
        <message>
            <source>Tool library</source>
            <translation>刀具库</translation>
        </message>
        <message>
            <source>T</source>
            <translation>T</translation>
        </message>
        <message>
            <source>Name</source>
            <translation>名称</translation>
        </message>
        <message>
            <source>Type</source>
            <translation>类型</translation>
        </message>
        <message>
            <source>Ø mm</source>
            <translation>Ø mm</translation>
        </message>
        <message>
            <source>Corner r</source>
            <translation>刀尖 r</translation>
        </message>
        <message>
            <source>Taper °</source>
            <translation>锥度 °</translation>
        </message>
        <message>
            <source>Flutes</source>
            <translation>刃数</translation>
        </message>
        <message>
            <source>Flute mm</source>
            <translation>刃长 mm</translation>
        </message>
        <message>
            <source>Stick-out mm</source>
            <translation>伸出长度 mm</translation>
        </message>
        <message>
            <source>Holder</source>
            <translation>刀柄</translation>
        </message>
        <message>
            <source>Holder Ø mm</source>
            <translation>刀柄 Ø mm</translation>
        </message>
        <message>
            <source>Life min</source>
            <translation>寿命 分钟</translation>
        </message>
        <message>
            <source>Used min</source>
            <translation>已用 分钟</translation>
        </message>
        <message>
            <source>&amp;Copy</source>
            <translation>复制(&amp;C)</translation>
        </message>
        <message>
            <source>Re&amp;tire</source>
            <translation>报废(&amp;T)</translation>
        </message>
        <message>
            <source>&amp;Undo</source>
            <translation>撤销(&amp;U)</translation>
        </message>
        <message>
            <source>&amp;Export tool table…</source>
            <translation>导出刀具表(&amp;E)…</translation>
        </message>
        <message numerus="yes">
            <source>%1 — %n tool(s)</source>
            <translation>
                <numerusform>%1 — %n 把刀具</numerusform>
            </translation>
        </message>
        <message>
            <source>Cannot read the tool library: %1</source>
            <translation>无法读取刀具库:%1</translation>
        </message>
        <message>
            <source>Select a tool first.</source>
            <translation>请先选择一把刀具。</translation>
        </message>
        <message>
            <source>T%1 not saved: %2 '%3' is not a number</source>
            <translation>T%1 未保存：%2 的“%3”不是数字</translation>
        </message>
        <message>
            <source>T%1: %2 changed</source>
            <translation>T%1：%2 已修改</translation>
        </message>
        <message>
            <source>No free T number: the library uses T%1</source>
            <translation>没有空闲的 T 号：刀具库已用到 T%1</translation>
        </message>
        <message>
            <source>T%1 copied to T%2</source>
            <translation>T%1 已复制为 T%2</translation>
        </message>
        <message>
            <source>T%1 retired (Undo brings it back)</source>
            <translation>T%1 已报废（撤销可恢复）</translation>
        </message>
        <message>
            <source>T%1: wear reset</source>
            <translation>T%1：磨损已重置</translation>
        </message>
        <message>
            <source>Cannot write %1: %2</source>
            <translation>无法写入 %1：%2</translation>
        </message>
        <message>
            <source>Tool table written to %1</source>
            <translation>刀具表已写入 %1</translation>
        </message>
        <message>
            <source>LinuxCNC tool table (*.tbl)</source>
            <translation>LinuxCNC 刀具表 (*.tbl)</translation>
        </message>
        <message>
            <source>FANUC offset program, G10 (*.nc)</source>
            <translation>FANUC 偏置程序，G10 (*.nc)</translation>
        </message>
        <message>
            <source>Export tool table</source>
            <translation>导出刀具表</translation>
        </message>
        <message>
            <source>%1, Ø %2 mm, %3 flutes, stick-out %4 mm, holder %5, used %6 of %7 min</source>
            <translation>%1，Ø %2 mm，%3 刃，伸出 %4 mm，刀柄 %5，已用 %6 / %7 分钟</translation>
        </message>
        <message>
            <source>Cannot retire the tool: %1</source>
            <translation>无法报废刀具：%1</translation>
        </message>
        <message>
            <source>Cannot save the tool: %1</source>
            <translation>无法保存刀具:%1</translation>
        </message>
        <message>
            <source>Tool changed meanwhile</source>
            <translation>刀具已被更改</translation>
        </message>
        <message>
            <source>T%1 was changed by %2 at station %3 (%4) after this station read it.

Yours: %5
Theirs: %6</source>
            <translation>T%1 在本工位读取后已由 %2 在工位 %3 更改（%4）。

我的：%5
对方的：%6</translation>
        </message>
        <message>
            <source>removed</source>
            <translation>已删除</translation>
        </message>
        <message>
            <source>Keep mine</source>
            <translation>保留我的</translation>
        </message>
        <message>
            <source>Take theirs</source>
            <translation>采用对方的</translation>
        </message>
        <message>
            <source>T%1 was changed again meanwhile; nothing saved</source>
            <translation>T%1 期间再次被更改；未保存</translation>
        </message>
        <message>
            <source>T%1: theirs taken, yours not saved</source>
            <translation>T%1：已采用对方的，我的未保存</translation>
        </message>
        <message>
            <source>Cannot open the tool library: %1</source>
            <translation>无法打开刀具库：%1</translation>
        </message>
        <message numerus="yes">
            <source>This changes %n step(s) of the open job:</source>
            <translation>
                <numerusform>此更改将改变当前作业的 %n 个工步:</numerusform>
            </translation>
        </message>
        <message>
            <source>no tool</source>
            <translation>无刀具</translation>
        </message>
        <message>
            <source>unit %1, %2</source>
            <translation>单元 %1，%2</translation>
        </message>
        <message>
            <source>  %1: %2, its data changed</source>
            <translation>  %1: %2（刀具数据已改变）</translation>
        </message>
        <message>
            <source>  %1: no tool</source>
            <translation>  %1: 无刀具</translation>
        </message>
        <message>
            <source>  %1: %2 → %3</source>
            <translation>  %1: %2 → %3</translation>
        </message>
        <message>
            <source>The job would be refused:</source>
            <translation>作业将被拒绝:</translation>
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
            <translation>应用此更改吗?</translation>
        </message>
        <message>
            <source>T%1 not saved: %2</source>
            <translation>T%1 未保存：%2</translation>
        </message>
        <message>
            <source>Change the tool?</source>
            <translation>更改刀具吗?</translation>
        </message>
        <message>
            <source>T%1 not changed</source>
            <translation>T%1 未更改</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::TwoPathChart</name>
        <message>
            <source>Path %1 (%2)</source>
            <translation>系统 %1（%2）</translation>
        </message>
        <message>
            <source>CB%1 in, dwell %2 s</source>
            <translation>CB%1 进入，暂停 %2 秒</translation>
        </message>
        <message>
            <source>CB%1 in</source>
            <translation>CB%1 进入</translation>
        </message>
        <message>
            <source>CB%1 cut</source>
            <translation>CB%1 切削</translation>
        </message>
        <message>
            <source>CB%1 out</source>
            <translation>CB%1 退出</translation>
        </message>
        <message>
            <source>M%1 wait</source>
            <translation>M%1 等待</translation>
        </message>
        <message>
            <source>M%1 met</source>
            <translation>M%1 会合</translation>
        </message>
        <message>
            <source>back to the safe point, end wait</source>
            <translation>回到安全点，结束等待</translation>
        </message>
        <message>
            <source>No balanced roughing on the timeline</source>
            <translation>时间线上没有平衡粗车</translation>
        </message>
        <message>
            <source>%1 s on %2 paths</source>
            <translation>%2 个系统共 %1 秒</translation>
        </message>
        <message>
            <source>Path %1: %2, %3–%4 s</source>
            <translation>系统 %1：%2，%3–%4 秒</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::TwoPathSteps</name>
        <message>
            <source>Path, step</source>
            <translation>系统、工步</translation>
        </message>
        <message>
            <source>Tool</source>
            <translation>刀具</translation>
        </message>
        <message>
            <source>Time</source>
            <translation>时间</translation>
        </message>
        <message>
            <source>Path %1 (%2): turret with %3</source>
            <translation>系统 %1（%2）：刀塔上 %3</translation>
        </message>
        <message>
            <source>no tool</source>
            <translation>无刀具</translation>
        </message>
        <message>
            <source>%1, balanced: %2</source>
            <translation>%1，平衡：%2</translation>
        </message>
        <message>
            <source>CB%1: cut %2–%3 s</source>
            <translation>CB%1：切削 %2–%3 秒</translation>
        </message>
        <message>
            <source>wait M%1</source>
            <translation>等待 M%1</translation>
        </message>
        <message>
            <source>dwell %1 s</source>
            <translation>暂停 %1 秒</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::TwoPathViews</name>
        <message>
            <source>No roughing step to balance between the paths: path 2 has no program.</source>
            <translation>没有可在系统间平衡的粗车工步：系统 2 没有程序。</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::UnitForm</name>
        <message>
            <source>optional, e.g. Pocket A</source>
            <translation>可选,例如 型腔 A</translation>
        </message>
        <message>
            <source>Unit name</source>
            <translation>单元名称</translation>
        </message>
        <message>
            <source>not a whole number</source>
            <translation>不是整数</translation>
        </message>
        <message>
            <source>not a number</source>
            <translation>不是数字</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::UnitListPanel</name>
        <message>
            <source>D&amp;uplicate</source>
            <translation>复制(&amp;U)</translation>
        </message>
        <message>
            <source>▲ U&amp;p</source>
            <translation>▲ 上移(&amp;P)</translation>
        </message>
        <message>
            <source>▼ Do&amp;wn</source>
            <translation>▼ 下移(&amp;W)</translation>
        </message>
        <message>
            <source>De&amp;lete</source>
            <translation>删除(&amp;L)</translation>
        </message>
        <message>
            <source>Add %1 unit</source>
            <translation>添加 %1 单元</translation>
        </message>
        <message>
            <source>Added where it overlaps another unit: the stock has no free place for it. Type its corners, or make the stock larger.</source>
            <translation>已添加在与其他单元重叠的位置：毛坯上没有空位。请输入其角点，或加大毛坯。</translation>
        </message>
        <message>
            <source>No unit added: the stock has no free place for it. Make the stock larger or a unit smaller, or move one.</source>
            <translation>未添加单元:毛坯上没有空位。请加大毛坯、缩小单元或移动其他单元。</translation>
        </message>
        <message>
            <source>Duplicate unit %1</source>
            <translation>复制单元 %1</translation>
        </message>
        <message>
            <source>Move unit %1</source>
            <translation>移动单元 %1</translation>
        </message>
        <message>
            <source>Delete unit %1</source>
            <translation>删除单元 %1</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::VerificationPanel</name>
        <message>
            <source>&amp;Verify</source>
            <translation>验证(&amp;V)</translation>
        </message>
        <message>
            <source>Cut every step into the stock on a %1 mm grid and list gouges, collisions, rapids into stock, travel limits and material left</source>
            <translation>以 %1 mm 网格将所有工步切入毛坯，列出过切、碰撞、快移撞入毛坯、超出行程和残料</translation>
        </message>
        <message>
            <source>Colour &amp;map</source>
            <translation>色彩图(&amp;M)</translation>
        </message>
        <message>
            <source>Show the finished part in the 3-D view coloured by what the verification found</source>
            <translation>在三维视图中按验证结果着色显示成品零件</translation>
        </message>
        <message>
            <source>gouge</source>
            <translation>过切</translation>
        </message>
        <message>
            <source>at size</source>
            <translation>尺寸合格</translation>
        </message>
        <message>
            <source>up to %1 mm left</source>
            <translation>残留不超过 %1 mm</translation>
        </message>
        <message>
            <source>more left</source>
            <translation>残留更多</translation>
        </message>
        <message>
            <source>Verifying…</source>
            <translation>正在验证…</translation>
        </message>
        <message>
            <source>Not verified since the last change.</source>
            <translation>自上次修改后尚未验证。</translation>
        </message>
        <message>
            <source>No plan to verify.</source>
            <translation>没有可验证的加工计划。</translation>
        </message>
        <message>
            <source>Not verified: %1</source>
            <translation>未验证：%1</translation>
        </message>
        <message>
            <source>Verified at %1 mm: clean.</source>
            <translation>已按 %1 mm 验证：无问题。</translation>
        </message>
        <message>
            <source>Verified at %1 mm: %2 faults, %3 with material left.</source>
            <translation>已按 %1 mm 验证：%2 处故障，%3 处残料。</translation>
        </message>
    </context>
    <context>
        <name>taiwa::CoreTexts</name>
        <message>
            <source>Pilot hole</source>
            <translation>预钻孔</translation>
        </message>
        <message>
            <source>Roughing</source>
            <translation>粗加工</translation>
        </message>
        <message>
            <source>Floor finishing</source>
            <translation>底面精加工</translation>
        </message>
        <message>
            <source>Wall finishing</source>
            <translation>侧壁精加工</translation>
        </message>
        <message>
            <source>Inclined-face finishing</source>
            <translation>斜面精加工</translation>
        </message>
        <message>
            <source>Facing</source>
            <translation>车端面</translation>
        </message>
        <message>
            <source>Centre drilling</source>
            <translation>中心钻孔</translation>
        </message>
        <message>
            <source>Drilling</source>
            <translation>钻孔</translation>
        </message>
        <message>
            <source>Grooving</source>
            <translation>切槽</translation>
        </message>
        <message>
            <source>Finishing</source>
            <translation>精加工</translation>
        </message>
        <message>
            <source>Threading</source>
            <translation>车螺纹</translation>
        </message>
        <message>
            <source>Parting off</source>
            <translation>切断</translation>
        </message>
        <message>
            <source>Tapping</source>
            <translation>攻丝</translation>
        </message>
        <message>
            <source>Reaming</source>
            <translation>铰孔</translation>
        </message>
        <message>
            <source>Boring</source>
            <translation>镗孔</translation>
        </message>
        <message>
            <source>roughing, floor finishing and wall finishing</source>
            <translation>粗加工、底面精加工和侧壁精加工</translation>
        </message>
        <message>
            <source>roughing and floor finishing, walls left as roughed</source>
            <translation>粗加工和底面精加工，侧壁保持粗加工状态</translation>
        </message>
        <message>
            <source>floor and wall finishing of a pocket already cored</source>
            <translation>已预加工型腔的底面和侧壁精加工</translation>
        </message>
        <message>
            <source>wall finishing only</source>
            <translation>仅侧壁精加工</translation>
        </message>
        <message>
            <source>roughing only</source>
            <translation>仅粗加工</translation>
        </message>
        <message>
            <source>walls finished to full depth in one incision</source>
            <translation>侧壁一次切入全深精加工</translation>
        </message>
        <message>
            <source>walls finished in several Z incisions down to the floor</source>
            <translation>侧壁分多次 Z 向切入精加工到底面</translation>
        </message>
        <message>
            <source>walls semi-finished leaving alpha3, then finished</source>
            <translation>侧壁半精加工留 α3 后精加工</translation>
        </message>
        <message>
            <source>drill a pilot hole first</source>
            <translation>先钻预钻孔</translation>
        </message>
        <message>
            <source>no pilot hole, the roughing tool ramps in</source>
            <translation>无预钻孔，粗加工刀具斜线下刀</translation>
        </message>
        <message>
            <source>round (boss or bore)</source>
            <translation>圆形（凸台或孔）</translation>
        </message>
        <message>
            <source>rectangular (block or pocket)</source>
            <translation>矩形（块或型腔）</translation>
        </message>
        <message>
            <source>outside (boss, block)</source>
            <translation>外侧（凸台、块）</translation>
        </message>
        <message>
            <source>inside (bore, pocket)</source>
            <translation>内侧（孔、型腔）</translation>
        </message>
        <message>
            <source>(round: none)</source>
            <translation>（圆形：无）</translation>
        </message>
        <message>
            <source>outer (OD)</source>
            <translation>外轮廓（外径）</translation>
        </message>
        <message>
            <source>inner (ID, a bore)</source>
            <translation>内轮廓（内径，孔）</translation>
        </message>
        <message>
            <source>Face milling</source>
            <translation>面铣</translation>
        </message>
        <message>
            <source>Side milling</source>
            <translation>侧铣</translation>
        </message>
        <message>
            <source>Area clearing</source>
            <translation>区域加工</translation>
        </message>
        <message>
            <source>roughing layers and a finishing pass</source>
            <translation>粗加工层和精加工刀路</translation>
        </message>
        <message>
            <source>roughing only, the finishing pass left</source>
            <translation>仅粗加工，留出精加工余量</translation>
        </message>
        <message>
            <source>one way, every pass climb</source>
            <translation>单向，每条刀路顺铣</translation>
        </message>
        <message>
            <source>zigzag, back and forth</source>
            <translation>之字形，往复</translation>
        </message>
        <message>
            <source>left of the contour</source>
            <translation>轮廓左侧</translation>
        </message>
        <message>
            <source>right of the contour</source>
            <translation>轮廓右侧</translation>
        </message>
        <message>
            <source>climb</source>
            <translation>顺铣</translation>
        </message>
        <message>
            <source>conventional</source>
            <translation>逆铣</translation>
        </message>
        <message>
            <source>roughing and finishing</source>
            <translation>粗加工和精加工</translation>
        </message>
        <message>
            <source>finishing only</source>
            <translation>仅精加工</translation>
        </message>
        <message>
            <source>full depth at once</source>
            <translation>全深度一次完成</translation>
        </message>
        <message>
            <source>several incisions</source>
            <translation>分多次切入</translation>
        </message>
        <message>
            <source>single</source>
            <translation>单孔</translation>
        </message>
        <message>
            <source>line</source>
            <translation>直线排列</translation>
        </message>
        <message>
            <source>grid</source>
            <translation>网格排列</translation>
        </message>
        <message>
            <source>bolt circle</source>
            <translation>圆周分布 (PCD)</translation>
        </message>
        <message>
            <source>arc</source>
            <translation>圆弧排列</translation>
        </message>
        <message>
            <source>drilled</source>
            <translation>钻孔</translation>
        </message>
        <message>
            <source>tapped</source>
            <translation>螺纹孔</translation>
        </message>
        <message>
            <source>reamed</source>
            <translation>铰孔</translation>
        </message>
        <message>
            <source>bored</source>
            <translation>镗孔</translation>
        </message>
        <message>
            <source>the library has no tools</source>
            <translation>刀具库中没有刀具</translation>
        </message>
        <message>
            <source>axes %1 mm</source>
            <translation>坐标轴 %1 mm</translation>
        </message>
    </context>
    <context>
        <name>taiwa::Field</name>
        <message>
            <source>figure</source>
            <translation>图形</translation>
        </message>
        <message>
            <source>workOffset</source>
            <translation>工件坐标系</translation>
        </message>
        <message>
            <source>stock</source>
            <translation>毛坯</translation>
        </message>
        <message>
            <source>clamping</source>
            <translation>装夹</translation>
        </message>
        <message>
            <source>technology</source>
            <translation>工艺参数</translation>
        </message>
        <message>
            <source>name</source>
            <translation>名称</translation>
        </message>
        <message>
            <source>material</source>
            <translation>材料</translation>
        </message>
        <message>
            <source>machine</source>
            <translation>机床</translation>
        </message>
        <message>
            <source>dialect</source>
            <translation>数控系统</translation>
        </message>
        <message>
            <source>lengthUnit</source>
            <translation>长度单位</translation>
        </message>
        <message>
            <source>format</source>
            <translation>格式</translation>
        </message>
        <message>
            <source>version</source>
            <translation>版本</translation>
        </message>
        <message>
            <source>units</source>
            <translation>单元</translation>
        </message>
        <message>
            <source>latheRoughing</source>
            <translation>车削粗加工</translation>
        </message>
        <message>
            <source>height</source>
            <translation>高度</translation>
        </message>
        <message>
            <source>width</source>
            <translation>宽度</translation>
        </message>
        <message>
            <source>length</source>
            <translation>长度</translation>
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
            <translation>内孔</translation>
        </message>
        <message>
            <source>shape</source>
            <translation>形状</translation>
        </message>
        <message>
            <source>fixture</source>
            <translation>夹具</translation>
        </message>
        <message>
            <source>grip</source>
            <translation>夹持方向</translation>
        </message>
        <message>
            <source>touches</source>
            <translation>触碰点</translation>
        </message>
        <message>
            <source>cutting</source>
            <translation>切削参数</translation>
        </message>
        <message>
            <source>module</source>
            <translation>模块</translation>
        </message>
        <message>
            <source>unit</source>
            <translation>单元</translation>
        </message>
    </context>
    <context>
        <name>taiwa::PathNames</name>
        <message>
            <source>upper turret</source>
            <translation>上刀塔</translation>
        </message>
        <message>
            <source>lower turret</source>
            <translation>下刀塔</translation>
        </message>
    </context>
    <context>
        <name>taiwa::msg</name>
        <message>
            <source>the library has no tools</source>
            <translation>刀具库中没有刀具</translation>
        </message>
        <message>
            <source>T{} ({} {}, nose R{} mm)</source>
            <translation>T{} ({} {}，刀尖R{} mm)</translation>
        </message>
        <message>
            <source>T{} ({} Ø{} mm, {} per side)</source>
            <translation>T{} ({} Ø{} mm，单边 {})</translation>
        </message>
        <message>
            <source>T{} ({} Ø{} mm)</source>
            <translation>T{} ({} Ø{} mm)</translation>
        </message>
        <message>
            <source>{} is not a finite number; type a number</source>
            <translation>{} 不是有限数值；请输入数字</translation>
        </message>
        <message>
            <source>material "{}" is not in the technology table; known materials: {}</source>
            <translation>材料“{}”不在工艺表中；已知材料：{}</translation>
        </message>
        <message>
            <source>the stock {} is {}; it must be greater than zero</source>
            <translation>毛坯的{}为 {}；必须大于零</translation>
        </message>
        <message>
            <source>{} = {}{} must be greater than zero</source>
            <translation>{} = {}{} 必须大于零</translation>
        </message>
        <message>
            <source>the pilot-hole remainder α1 = {} is not smaller than the depth {} of unit {}: the pilot hole would have no depth; use H = 9 or a smaller α1</source>
            <translation>预钻孔余量 α1 = {0} 不小于单元 {2} 的深度 {1}：预钻孔将没有深度；请使用 H = 9 或减小 α1</translation>
        </message>
        <message>
            <source>the floor allowance β2 = {} is not smaller than the depth {} of unit {}: roughing would not cut at all</source>
            <translation>底面余量 β2 = {0} 不小于单元 {2} 的深度 {1}：粗加工将完全不切削</translation>
        </message>
        <message>
            <source>{} is {}; every length and coordinate must lie within ±{} of the origin (beyond it a micrometre is no longer exact on the tape)</source>
            <translation>{} 为 {}；所有长度和坐标都必须在原点 ±{} 以内（超出后程序中 1 微米不再精确）</translation>
        </message>
        <message>
            <source>{} is {:g}{}; it must lie between {:g} and {:g}{} ({})</source>
            <translation>{} 为 {}{}；必须在 {} 到 {}{} 之间（{}）</translation>
        </message>
        <message>
            <source>the stock {} is {}; a stock of more than {} a side is not a part for this station</source>
            <translation>毛坯的{}为 {}；单边超过 {} 的毛坯不适用于本工作站</translation>
        </message>
        <message>
            <source>the depth is {}; it must be greater than zero (measured down from the top face)</source>
            <translation>深度为 {}；必须大于零（自顶面向下测量）</translation>
        </message>
        <message>
            <source>the depth {} is deeper than the stock, which is {} high</source>
            <translation>深度 {} 超过了毛坯高度 {}</translation>
        </message>
        <message>
            <source>{} is {}; it must be greater than zero</source>
            <translation>{} 为 {}；必须大于零</translation>
        </message>
        <message>
            <source>the figure of unit {} overlaps the figure of unit {} by {} {}²; figures of one job may touch but not overlap</source>
            <translation>单元 {} 的图形与单元 {} 的图形重叠 {} {}²；同一作业的图形可以相接但不能重叠</translation>
        </message>
        <message>
            <source>"{}" is not a step of module {}; its steps are {}</source>
            <translation>“{}”不是模块 {} 的工序；其工序为 {}</translation>
        </message>
        <message>
            <source>module {} has no cutting steps to set a speed or feed for</source>
            <translation>模块 {} 没有可设置转速或进给的切削工序</translation>
        </message>
        <message>
            <source>{} {:g} {} is out of range: give {:g} to {:g} {}{}</source>
            <translation>{} {} {} 超出范围：请给出 {} 到 {} {}{}</translation>
        </message>
        <message>
            <source>tool T{} is not in the tool library</source>
            <translation>刀具 T{} 不在刀具库中</translation>
        </message>
        <message>
            <source>the tool library has no {}; add one to machine this pocket</source>
            <translation>刀具库中没有{}；请添加一把以加工此型腔</translation>
        </message>
        <message>
            <source>no taper end mill of {} per side in the tool library (it has none)</source>
            <translation>刀具库中没有单边 {} 的锥度立铣刀（一把也没有）</translation>
        </message>
        <message>
            <source>no taper end mill of {} per side in the tool library (it has {})</source>
            <translation>刀具库中没有单边 {} 的锥度立铣刀（已有 {}）</translation>
        </message>
        <message>
            <source>{} = {} is smaller than the radius of the smallest suitable tool, {}; no tool of the library fits: a corner radius of at least {} would let it fit</source>
            <translation>{} = {} 小于最小合适刀具 {} 的半径；刀具库中没有能放入的刀具：圆角半径至少为 {} 才能放入</translation>
        </message>
        <message>
            <source>{} would fit</source>
            <translation>{} 可以放入</translation>
        </message>
        <message>
            <source>no tool of that kind in the library fits</source>
            <translation>刀具库中没有该类型可放入的刀具</translation>
        </message>
        <message>
            <source>the {} tool {} is too big for {} = {}; {}</source>
            <translation>{}刀具 {} 对于 {} = {} 过大；{}</translation>
        </message>
        <message>
            <source>the step-over</source>
            <translation>行距</translation>
        </message>
        <message>
            <source>{}, {}</source>
            <translation>{}, {}</translation>
        </message>
        <message>
            <source>more than {} ends meet at {} or near it: {}, …; the nearest were joined, the rest left open</source>
            <translation>超过 {0} 个端点汇集于 {1} 或其附近：{2}, …；已连接最近的端点，其余保持开放</translation>
        </message>
        <message>
            <source>more than {} ends meet at {} or near it: {}; the nearest were joined, the rest left open</source>
            <translation>超过 {0} 个端点汇集于 {1} 或其附近：{2}；已连接最近的端点，其余保持开放</translation>
        </message>
        <message>
            <source>{} ends meet at {}: {}, …; the nearest were joined, the rest left open</source>
            <translation>{0} 个端点汇集于 {1}：{2}, …；已连接最近的端点，其余保持开放</translation>
        </message>
        <message>
            <source>{} ends meet at {}: {}; the nearest were joined, the rest left open</source>
            <translation>{0} 个端点汇集于 {1}：{2}；已连接最近的端点，其余保持开放</translation>
        </message>
        <message>
            <source>gap of {:.4g} mm at {} between {} and {}, whose end is at {}; the gap tolerance is {:.4g} mm</source>
            <translation>{1} 处 {2} 与 {3}（其端点在 {4}）之间有 {0} mm 的间隙；间隙容差为 {5} mm</translation>
        </message>
        <message>
            <source>its plane is not the XY plane (extrusion {:.4g}, {:.4g}, {:.4g})</source>
            <translation>其平面不是 XY 平面（拉伸方向 {}, {}, {}）</translation>
        </message>
        <message>
            <source>it leaves the XY plane (its ends differ in Z)</source>
            <translation>偏离 XY 平面（两端 Z 值不同）</translation>
        </message>
        <message>
            <source>{} not read: {}</source>
            <translation>未读取 {}：{}</translation>
        </message>
        <message>
            <source>it has no length</source>
            <translation>长度为零</translation>
        </message>
        <message>
            <source>its radius {:g} is not positive</source>
            <translation>半径 {} 不是正数</translation>
        </message>
        <message>
            <source>its major axis leaves the XY plane</source>
            <translation>长轴偏离 XY 平面</translation>
        </message>
        <message>
            <source>it is degenerate (axis {:g}, ratio {:g})</source>
            <translation>已退化（轴 {}，比率 {}）</translation>
        </message>
        <message>
            <source>its parameters are out of range</source>
            <translation>参数超出范围</translation>
        </message>
        <message>
            <source>it needs more than {} lines at the spline tolerance</source>
            <translation>按样条容差需要超过 {} 条直线</translation>
        </message>
        <message>
            <source>it leaves the XY plane (its vertices differ in Z)</source>
            <translation>偏离 XY 平面（顶点 Z 值不同）</translation>
        </message>
        <message>
            <source>{}: a bulge of {:g} read as a straight line</source>
            <translation>{}：凸度 {} 按直线读取</translation>
        </message>
        <message>
            <source>its {} vertices give no segment</source>
            <translation>其 {} 个顶点构不成线段</translation>
        </message>
        <message>
            <source>it is given by fit points only, without control points</source>
            <translation>只有拟合点，没有控制点</translation>
        </message>
        <message>
            <source>it has no control points</source>
            <translation>没有控制点</translation>
        </message>
        <message>
            <source>its degree {} is not 1 to 20</source>
            <translation>次数 {} 不在 1 到 20 之间</translation>
        </message>
        <message>
            <source>{} knots do not fit {} control points of degree {}</source>
            <translation>{0} 个节点与次数为 {2} 的 {1} 个控制点不符</translation>
        </message>
        <message>
            <source>its knots decrease</source>
            <translation>节点递减</translation>
        </message>
        <message>
            <source>its knots span nothing</source>
            <translation>节点范围为空</translation>
        </message>
        <message>
            <source>it leaves the XY plane (its control points differ in Z)</source>
            <translation>偏离 XY 平面（控制点 Z 值不同）</translation>
        </message>
        <message>
            <source>a weight {:g} is not positive</source>
            <translation>权重 {} 不是正数</translation>
        </message>
        <message>
            <source>the drawing needs more than {} segments: too large or too fine a spline tolerance</source>
            <translation>图纸需要超过 {} 条线段：图纸过大或样条容差过细</translation>
        </message>
        <message>
            <source>inch</source>
            <translation>英寸</translation>
        </message>
        <message>
            <source>foot</source>
            <translation>英尺</translation>
        </message>
        <message>
            <source>mile</source>
            <translation>英里</translation>
        </message>
        <message>
            <source>microinch</source>
            <translation>微英寸</translation>
        </message>
        <message>
            <source>mil</source>
            <translation>密耳</translation>
        </message>
        <message>
            <source>yard</source>
            <translation>码</translation>
        </message>
        <message>
            <source>ångström</source>
            <translation>埃</translation>
        </message>
        <message>
            <source>none</source>
            <translation>无</translation>
        </message>
        <message>
            <source>the gap tolerance {:g} mm is not between 0.000001 and 10 mm</source>
            <translation>间隙容差 {} mm 不在 0.000001 到 10 mm 之间</translation>
        </message>
        <message>
            <source>the spline tolerance {:g} mm is not between 0.0001 and 10 mm</source>
            <translation>样条容差 {} mm 不在 0.0001 到 10 mm 之间</translation>
        </message>
        <message>
            <source>the gap report distance {:g} mm is not between 0 and 1000 mm</source>
            <translation>间隙报告距离 {} mm 不在 0 到 1000 mm 之间</translation>
        </message>
        <message>
            <source>{} on layer {} (DXF line {})</source>
            <translation>图层 {1} 上的 {0}（DXF 第 {2} 行）</translation>
        </message>
        <message>
            <source>{} on layer {}</source>
            <translation>图层 {1} 上的 {0}</translation>
        </message>
        <message>
            <source>cannot read {}: {}</source>
            <translation>无法读取 {}：{}</translation>
        </message>
        <message>
            <source>{} is larger than 256 MB</source>
            <translation>{} 大于 256 MB</translation>
        </message>
        <message>
            <source>cannot open {}: {}</source>
            <translation>无法打开 {}：{}</translation>
        </message>
        <message>
            <source>cannot read {}</source>
            <translation>无法读取 {}</translation>
        </message>
        <message>
            <source>the drawing has no layer {}</source>
            <translation>图纸中没有图层 {}</translation>
        </message>
        <message>
            <source>the drawing's units ($INSUNITS {}) are not lengths to machine in</source>
            <translation>图纸单位（$INSUNITS {}）不是可用于加工的长度单位</translation>
        </message>
        <message>
            <source>the drawing does not say its units ($INSUNITS unitless or absent): read as mm</source>
            <translation>图纸未指明单位（$INSUNITS 为无单位或缺失）：按 mm 读取</translation>
        </message>
        <message>
            <source>the drawing says its units are {}; read as {} as set</source>
            <translation>图纸单位为 {}；按设置以 {} 读取</translation>
        </message>
        <message>
            <source>no lines, arcs, circles, polylines, splines or ellipses on the drawing's layers; the drawing's layers: {}</source>
            <translation>图纸的图层上没有直线、圆弧、圆、多段线、样条或椭圆；图纸的图层：{}</translation>
        </message>
        <message>
            <source>no lines, arcs, circles, polylines, splines or ellipses on the selected layers; the drawing's layers: {}</source>
            <translation>所选图层上没有直线、圆弧、圆、多段线、样条或椭圆；图纸的图层：{}</translation>
        </message>
        <message>
            <source>none of the entities on the selected layers could be read (see the warnings)</source>
            <translation>所选图层上的实体均无法读取（见警告）</translation>
        </message>
        <message>
            <source>{} gaps up to {:.4g} mm closed (the largest at ({:.3f}, {:.3f})); the gap tolerance is {:.4g} mm</source>
            <translation>已闭合 {0} 处最大 {1} mm 的间隙（最大处在 ({2}, {3})）；间隙容差为 {4} mm</translation>
        </message>
        <message>
            <source>… and {} more warnings like these</source>
            <translation>… 另有 {} 条类似警告</translation>
        </message>
        <message>
            <source>line {}: '{}' stands where a DXF group code belongs: not a DXF file, or a damaged one</source>
            <translation>第 {0} 行：DXF 组码的位置上是 '{1}'：不是 DXF 文件，或文件已损坏</translation>
        </message>
        <message>
            <source>{} entities in paper space not read</source>
            <translation>未读取图纸空间中的 {} 个实体</translation>
        </message>
        <message>
            <source>not read (no contour geometry): {} — block references are not expanded: explode them in the CAD program</source>
            <translation>未读取（非轮廓几何）：{} — 不展开块参照：请在 CAD 程序中将其分解</translation>
        </message>
        <message>
            <source>not read (no contour geometry): {}</source>
            <translation>未读取（非轮廓几何）：{}</translation>
        </message>
        <message>
            <source>line {}: POLYLINE without SEQEND, read up to its last VERTEX</source>
            <translation>第 {} 行：POLYLINE 没有 SEQEND，读取到其最后一个 VERTEX</translation>
        </message>
        <message>
            <source>line {}: POLYLINE mesh or polyface (flags {}) is no contour: not read</source>
            <translation>第 {} 行：POLYLINE 网格或多面网格（标志 {}）不是轮廓：未读取</translation>
        </message>
        <message>
            <source>line {}: {} not read: '{}' is not a finite number (within ±1e12)</source>
            <translation>第 {} 行：未读取 {}：'{}' 不是有限数字（±1e12 以内）</translation>
        </message>
        <message>
            <source>line {}: {} not read: '{}' is not an integer</source>
            <translation>第 {} 行：未读取 {}：'{}' 不是整数</translation>
        </message>
        <message>
            <source>line {}: SPLINE not read: {} weights for {} control points</source>
            <translation>第 {} 行：未读取 SPLINE：{} 个权重对应 {} 个控制点</translation>
        </message>
        <message>
            <source>the file is empty</source>
            <translation>文件为空</translation>
        </message>
        <message>
            <source>the file is larger than {} MB</source>
            <translation>文件大于 {} MB</translation>
        </message>
        <message>
            <source>a binary DXF: save the drawing as an ASCII DXF (R12 or later)</source>
            <translation>二进制 DXF：请将图纸另存为 ASCII DXF（R12 或更高版本）</translation>
        </message>
        <message>
            <source>not a DXF file: it holds binary data</source>
            <translation>不是 DXF 文件：含有二进制数据</translation>
        </message>
        <message>
            <source>not a DXF file: it starts with '{}'</source>
            <translation>不是 DXF 文件：以 '{}' 开头</translation>
        </message>
        <message>
            <source>not a DXF file: it has no SECTION</source>
            <translation>不是 DXF 文件：没有 SECTION</translation>
        </message>
        <message>
            <source>the DXF file has no ENTITIES section</source>
            <translation>DXF 文件没有 ENTITIES 段</translation>
        </message>
        <message>
            <source>the file ends in the middle of a group: it may be cut short</source>
            <translation>文件在组的中间结束：可能不完整</translation>
        </message>
        <message>
            <source>the file ends without EOF: it may be cut short</source>
            <translation>文件没有 EOF 就结束：可能不完整</translation>
        </message>
        <message>
            <source>{}; nothing was changed in {}</source>
            <translation>{0}；{1} 中未做任何更改</translation>
        </message>
        <message>
            <source>the job did not pass input processing; nothing was written</source>
            <translation>作业未通过输入处理；未写入任何文件</translation>
        </message>
        <message>
            <source>{}; nothing was written</source>
            <translation>{}；未写入任何文件</translation>
        </message>
        <message>
            <source>unknown dialect '{}'; nothing was written</source>
            <translation>未知的数控系统 '{}'；未写入任何文件</translation>
        </message>
        <message>
            <source>cannot create folder {}: {}</source>
            <translation>无法创建文件夹 {}：{}</translation>
        </message>
        <message>
            <source>no PDF to join</source>
            <translation>没有要合并的 PDF</translation>
        </message>
        <message>
            <source>cannot join the sheet's PDF parts: {}</source>
            <translation>无法合并工艺单的 PDF 各部分: {}</translation>
        </message>
        <message>
            <source>cannot paint the instruction sheet's PDF</source>
            <translation>无法绘制工艺单的 PDF</translation>
        </message>
        <message>
            <source>it has no segments</source>
            <translation>没有线段</translation>
        </message>
        <message>
            <source>a closed contour of one line</source>
            <translation>只有一条直线的闭合轮廓</translation>
        </message>
        <message>
            <source>it reaches {}, beyond the ±1000000 mm the figure text can write</source>
            <translation>到达 {}，超出图形文本可写的 ±1000000 mm</translation>
        </message>
        <message>
            <source>the arc around {} has a radius of {:g} mm, which rounds to nothing</source>
            <translation>以 {} 为圆心的圆弧半径为 {} mm，舍入后为零</translation>
        </message>
        <message>
            <source>an arc's radius is beyond the 1000000 mm the figure text can write</source>
            <translation>圆弧半径超出图形文本可写的 1000000 mm</translation>
        </message>
        <message>
            <source>two of its lines no longer meet at {} once written to {:g} mm</source>
            <translation>按 {1} mm 写出后，其中两条直线不再交于 {0}</translation>
        </message>
        <message>
            <source>its elements cannot be evaluated: {}</source>
            <translation>其元素无法计算：{}</translation>
        </message>
        <message>
            <source>its elements {} and {} no longer meet at {} once written to {:g} mm</source>
            <translation>按 {3} mm 写出后，其元素 {0} 与 {1} 不再交于 {2}</translation>
        </message>
        <message>
            <source>{} and {} cross twice at {} within {:g} mm in x and in y: XLARGE, XSMALL, YLARGE and YSMALL cannot choose between the two</source>
            <translation>{0} 与 {1} 在 {2} 处两次相交，x 和 y 均相差在 {3} mm 以内：XLARGE、XSMALL、YLARGE 和 YSMALL 无法区分这两点</translation>
        </message>
        <message>
            <source>{} and {} are parallel: they do not meet</source>
            <translation>{} 与 {} 平行：不相交</translation>
        </message>
        <message>
            <source>{} and {} are concentric: they do not meet</source>
            <translation>{} 与 {} 同心：不相交</translation>
        </message>
        <message>
            <source>{} and {} do not meet</source>
            <translation>{} 与 {} 不相交</translation>
        </message>
        <message>
            <source>{} and {} meet twice: write XLARGE, XSMALL, YLARGE or YSMALL before {} to choose</source>
            <translation>{0} 与 {1} 相交两次：请在 {2} 前写 XLARGE、XSMALL、YLARGE 或 YSMALL 来选择</translation>
        </message>
        <message>
            <source>{} cannot choose between the two junctions of {} and {}: both have the same x; use YLARGE or YSMALL</source>
            <translation>{0} 无法在 {1} 与 {2} 的两个连接点中选择：两者 x 相同；请用 YLARGE 或 YSMALL</translation>
        </message>
        <message>
            <source>{} cannot choose between the two junctions of {} and {}: both have the same y; use XLARGE or XSMALL</source>
            <translation>{0} 无法在 {1} 与 {2} 的两个连接点中选择：两者 y 相同；请用 XLARGE 或 XSMALL</translation>
        </message>
        <message>
            <source>{} is not on {}: an open contour starts on its first element</source>
            <translation>{} 不在 {} 上：开放轮廓从其第一个元素上开始</translation>
        </message>
        <message>
            <source>{} is not on {}: an open contour ends on its last element</source>
            <translation>{} 不在 {} 上：开放轮廓在其最后一个元素上结束</translation>
        </message>
        <message>
            <source>its coordinates cannot be computed (a degenerate definition)</source>
            <translation>无法计算其坐标（退化的定义）</translation>
        </message>
        <message>
            <source>{} is of zero length between {} and {}</source>
            <translation>{0} 在 {1} 与 {2} 之间长度为零</translation>
        </message>
        <message>
            <source>ROUND {} between {} and {}</source>
            <translation>{1} 与 {2} 之间的 ROUND {0}</translation>
        </message>
        <message>
            <source>CHAMF {} between {} and {}</source>
            <translation>{1} 与 {2} 之间的 CHAMF {0}</translation>
        </message>
        <message>
            <source>{}: they meet tangentially, there is no corner</source>
            <translation>{}：两者相切，没有拐角</translation>
        </message>
        <message>
            <source>{}: {} turns back along {}, there is no corner</source>
            <translation>{0}：{1} 沿 {2} 折回，没有拐角</translation>
        </message>
        <message>
            <source>{} does not fit: it is not smaller than {}'s radius {}</source>
            <translation>{0} 放不下：不小于 {1} 的半径 {2}</translation>
        </message>
        <message>
            <source>{} does not fit: no circle of radius {} touches both in the corner</source>
            <translation>{0} 放不下：拐角处没有同时与两者相切的半径 {1} 的圆</translation>
        </message>
        <message>
            <source>{} does not fit: {} is {} mm long from the start {}</source>
            <translation>{0} 放不下：{1} 从起点 {3} 起只有 {2} mm 长</translation>
        </message>
        <message>
            <source>{} does not fit: {} is {} mm long from the previous corner</source>
            <translation>{0} 放不下：{1} 从上一个拐角起只有 {2} mm 长</translation>
        </message>
        <message>
            <source>{} does not fit: {} is {} mm long to the end {}</source>
            <translation>{0} 放不下：{1} 到终点 {3} 只有 {2} mm 长</translation>
        </message>
        <message>
            <source>{} does not fit: {} is {} mm long to the next corner</source>
            <translation>{0} 放不下：{1} 到下一个拐角只有 {2} mm 长</translation>
        </message>
        <message>
            <source>{} and {} coincide: no circle through three points</source>
            <translation>{} 与 {} 重合：无法作过三点的圆</translation>
        </message>
        <message>
            <source>{} cannot choose between the two {}: both have the same x; use YLARGE or YSMALL</source>
            <translation>{0} 无法在两个{1}中选择：两者 x 相同；请用 YLARGE 或 YSMALL</translation>
        </message>
        <message>
            <source>{} cannot choose between the two {}: both have the same y; use XLARGE or XSMALL</source>
            <translation>{0} 无法在两个{1}中选择：两者 y 相同；请用 XLARGE 或 XSMALL</translation>
        </message>
        <message>
            <source>{} names no side of {}: it is parallel to the X axis; use YLARGE or YSMALL</source>
            <translation>{0} 无法指定 {1} 的一侧：它平行于 X 轴；请用 YLARGE 或 YSMALL</translation>
        </message>
        <message>
            <source>{} names no side of {}: it is parallel to the Y axis; use XLARGE or XSMALL</source>
            <translation>{0} 无法指定 {1} 的一侧：它平行于 Y 轴；请用 XLARGE 或 XSMALL</translation>
        </message>
        <message>
            <source>{} and {} are parallel: they do not intersect</source>
            <translation>{} 与 {} 平行：没有交点</translation>
        </message>
        <message>
            <source>{} and {} are concentric: they do not intersect</source>
            <translation>{} 与 {} 同心：没有交点</translation>
        </message>
        <message>
            <source>{} and {} coincide: no line through them</source>
            <translation>{} 与 {} 重合：无法作过两点的直线</translation>
        </message>
        <message>
            <source>intersections of {} and {}</source>
            <translation>{} 与 {} 的交点</translation>
        </message>
        <message>
            <source>{} is inside {}: no tangent from it</source>
            <translation>{} 在 {} 内部：无法由此作切线</translation>
        </message>
        <message>
            <source>{} and {} are concentric: no common tangent</source>
            <translation>{} 与 {} 同心：没有公切线</translation>
        </message>
        <message>
            <source>{} and {} lie one inside the other: no tangent on the same side of both</source>
            <translation>{} 与 {} 一个在另一个内部：没有在两者同侧的切线</translation>
        </message>
        <message>
            <source>{} and {} overlap: no tangent crossing between them</source>
            <translation>{} 与 {} 重叠：没有从两者之间穿过的切线</translation>
        </message>
        <message>
            <source>{}, {} and {} lie on one line: no circle through them</source>
            <translation>{}、{} 和 {} 在一条直线上：无法作过它们的圆</translation>
        </message>
        <message>
            <source>radius {} is not smaller than {}'s radius {}: no circle inside it</source>
            <translation>半径 {0} 不小于 {1} 的半径 {2}：其内部放不下圆</translation>
        </message>
        <message>
            <source>no circle of radius {} on the {} side of {} touches {} from outside (the radius is too small or the side is wrong)</source>
            <translation>在 {2} 的 {1} 侧没有从外侧与 {3} 相切的半径 {0} 的圆（半径太小或侧向错误）</translation>
        </message>
        <message>
            <source>no circle of radius {} on the {} side of {} touches {} from inside (the radius is too small or the side is wrong)</source>
            <translation>在 {2} 的 {1} 侧没有从内侧与 {3} 相切的半径 {0} 的圆（半径太小或侧向错误）</translation>
        </message>
        <message>
            <source>centres</source>
            <translation>圆心</translation>
        </message>
        <message>
            <source>its text is refused: {}</source>
            <translation>其文本被拒绝：{}</translation>
        </message>
        <message>
            <source>its text gives back other segments</source>
            <translation>其文本还原出的线段不同</translation>
        </message>
        <message>
            <source>it comes back {:.7f} mm from the drawing</source>
            <translation>还原后与图纸偏差 {} mm</translation>
        </message>
        <message>
            <source>contour {} is left out: {}</source>
            <translation>轮廓 {} 已略去：{}</translation>
        </message>
        <message>
            <source>contour {} ({}) comes back {:.7f} mm from the drawing</source>
            <translation>轮廓 {}（{}）还原后与图纸偏差 {} mm</translation>
        </message>
        <message>
            <source>contour {} ({}) is written to {} mm: to 0.000001 mm {}</source>
            <translation>轮廓 {}（{}）按 {} mm 写出：按 0.000001 mm 时{}</translation>
        </message>
        <message>
            <source>a number</source>
            <translation>数字</translation>
        </message>
        <message>
            <source>a number (the y coordinate)</source>
            <translation>数字（y 坐标）</translation>
        </message>
        <message>
            <source>a circle name</source>
            <translation>圆名</translation>
        </message>
        <message>
            <source>in {}, {} and {} may meet twice: write XLARGE, XSMALL, YLARGE or YSMALL before INTOF to choose</source>
            <translation>在 {0} 中，{1} 与 {2} 可能相交两次：请在 INTOF 前写 XLARGE、XSMALL、YLARGE 或 YSMALL 来选择</translation>
        </message>
        <message>
            <source>in {}, two lines meet once: no {} before INTOF</source>
            <translation>在 {} 中，两条直线只相交一次：INTOF 前不要写 {}</translation>
        </message>
        <message>
            <source>a number, CENTER, INTOF or XLARGE/XSMALL/YLARGE/YSMALL</source>
            <translation>数字、CENTER、INTOF 或 XLARGE/XSMALL/YLARGE/YSMALL</translation>
        </message>
        <message>
            <source>a line name</source>
            <translation>直线名</translation>
        </message>
        <message>
            <source>a number (the distance)</source>
            <translation>数字（距离）</translation>
        </message>
        <message>
            <source>the distance</source>
            <translation>距离</translation>
        </message>
        <message>
            <source>a point name</source>
            <translation>点名</translation>
        </message>
        <message>
            <source>a number (the angle in degrees)</source>
            <translation>数字（角度，度）</translation>
        </message>
        <message>
            <source>a point name, ATANGL, LEFT or RIGHT</source>
            <translation>点名、ATANGL、LEFT 或 RIGHT</translation>
        </message>
        <message>
            <source>a point name, PARLEL, LEFT or RIGHT</source>
            <translation>点名、PARLEL、LEFT 或 RIGHT</translation>
        </message>
        <message>
            <source>a line name, OUT or IN</source>
            <translation>直线名、OUT 或 IN</translation>
        </message>
        <message>
            <source>CENTER, a point name or XLARGE/XSMALL/YLARGE/YSMALL</source>
            <translation>CENTER、点名或 XLARGE/XSMALL/YLARGE/YSMALL</translation>
        </message>
        <message>
            <source>a number (the radius)</source>
            <translation>数字（半径）</translation>
        </message>
        <message>
            <source>the radius</source>
            <translation>半径</translation>
        </message>
        <message>
            <source>in {}, {} is not defined: an element must be defined before it is used</source>
            <translation>在 {0} 中，{1} 未定义：元素必须先定义后使用</translation>
        </message>
        <message>
            <source>a line or circle name, CLW or CCLW</source>
            <translation>直线名或圆名、CLW 或 CCLW</translation>
        </message>
        <message>
            <source>an element name, XLARGE/XSMALL/YLARGE/YSMALL, CLW or CCLW</source>
            <translation>元素名、XLARGE/XSMALL/YLARGE/YSMALL、CLW 或 CCLW</translation>
        </message>
        <message>
            <source>in {}, {} ends the contour but no point starts it: an open contour runs from a point to a point</source>
            <translation>在 {0} 中，{1} 结束了轮廓，但轮廓没有起点：开放轮廓从一个点到一个点</translation>
        </message>
        <message>
            <source>in {}, {} after {} is not between two elements: the contour ends at {}</source>
            <translation>在 {0} 中，{2} 之后的 {1} 不在两个元素之间：轮廓在 {3} 结束</translation>
        </message>
        <message>
            <source>in {}, {} is a point: only the first and the last item of a contour may be points</source>
            <translation>在 {0} 中，{1} 是点：只有轮廓的第一项和最后一项可以是点</translation>
        </message>
        <message>
            <source>in {}, {} is {} where a circle is needed</source>
            <translation>在 {0} 中，{1} 是{2}，而此处需要圆</translation>
        </message>
        <message>
            <source>in {}, {} is {} where a line or a circle is needed</source>
            <translation>在 {0} 中，{1} 是{2}，而此处需要直线或圆</translation>
        </message>
        <message>
            <source>in {}, {} is a circle: write CLW or CCLW before it</source>
            <translation>在 {0} 中，{1} 是圆：请在其前写 CLW 或 CCLW</translation>
        </message>
        <message>
            <source>in {}, {} is a line: no {} before it (CLW and CCLW are for circles)</source>
            <translation>在 {0} 中，{1} 是直线：其前不要写 {2}（CLW 和 CCLW 用于圆）</translation>
        </message>
        <message>
            <source>in {}, {} follows itself: the same element twice in a row</source>
            <translation>在 {0} 中，{1} 紧跟自身：同一元素连续出现两次</translation>
        </message>
        <message>
            <source>in {}, {} starts at {}: no {} before it</source>
            <translation>在 {0} 中，{1} 从 {2} 开始：其前不要写 {3}</translation>
        </message>
        <message>
            <source>in {}, two lines meet once: no {} before {}</source>
            <translation>在 {0} 中，两条直线只相交一次：{2} 前不要写 {1}</translation>
        </message>
        <message>
            <source>a number (the chamfer)</source>
            <translation>数字（倒角）</translation>
        </message>
        <message>
            <source>the chamfer</source>
            <translation>倒角</translation>
        </message>
        <message>
            <source>in {}, the contour starts at {} and needs a point at its end, on {}</source>
            <translation>在 {0} 中，轮廓从 {1} 开始，需要在结尾处有一个位于 {2} 上的点</translation>
        </message>
        <message>
            <source>in {}, a closed contour needs two elements or more, or a single circle</source>
            <translation>在 {} 中，闭合轮廓需要两个或更多元素，或单个圆</translation>
        </message>
        <message>
            <source>in {}, {} alone is a full circle: no {} before it</source>
            <translation>在 {0} 中，只有 {1}，是整圆：其前不要写 {2}</translation>
        </message>
        <message>
            <source>in {}, {} alone is a full circle: no {} on it</source>
            <translation>在 {0} 中，只有 {1}，是整圆：不能加 {2}</translation>
        </message>
        <message>
            <source>in {}, {} follows itself: the same element twice in a row (the last element joins the first)</source>
            <translation>在 {0} 中，{1} 紧跟自身：同一元素连续出现两次（最后一个元素与第一个相接）</translation>
        </message>
        <message>
            <source>XLARGE, XSMALL, YLARGE or YSMALL</source>
            <translation>XLARGE、XSMALL、YLARGE 或 YSMALL</translation>
        </message>
        <message>
            <source>the end of the line</source>
            <translation>行尾</translation>
        </message>
        <message>
            <source>the end of the text</source>
            <translation>文本结尾</translation>
        </message>
        <message>
            <source>the character '{}'</source>
            <translation>字符 '{}'</translation>
        </message>
        <message>
            <source>expected {} after {}, found {}</source>
            <translation>{1} 之后应为{0}，实际为{2}</translation>
        </message>
        <message>
            <source>LEFT or RIGHT</source>
            <translation>LEFT 或 RIGHT</translation>
        </message>
        <message>
            <source>the number {} is out of range (at most 1000000 either way)</source>
            <translation>数字 {} 超出范围（正负最多 1000000）</translation>
        </message>
        <message>
            <source>{} must be greater than 0, found {}</source>
            <translation>{}必须大于 0，实际为 {}</translation>
        </message>
        <message>
            <source>in {}, {} is {} where {} is needed</source>
            <translation>在 {0} 中，{1} 是{2}，而此处需要{3}</translation>
        </message>
        <message>
            <source>a line or circle name</source>
            <translation>直线名或圆名</translation>
        </message>
        <message>
            <source>expected an element name at the start of a statement, found {}</source>
            <translation>语句开头应为元素名，实际为{}</translation>
        </message>
        <message>
            <source>'{}' is a word of the language and cannot name an element</source>
            <translation>'{}' 是语言的保留字，不能用作元素名</translation>
        </message>
        <message>
            <source>{} is already defined on line {}</source>
            <translation>{} 已在第 {} 行定义</translation>
        </message>
        <message>
            <source>POINT, LINE, CIRCLE or CONTOUR</source>
            <translation>POINT、LINE、CIRCLE 或 CONTOUR</translation>
        </message>
        <message>
            <source>the end of the statement</source>
            <translation>语句结尾</translation>
        </message>
        <message>
            <source>a point</source>
            <translation>点</translation>
        </message>
        <message>
            <source>a line</source>
            <translation>直线</translation>
        </message>
        <message>
            <source>a circle</source>
            <translation>圆</translation>
        </message>
        <message>
            <source>a contour</source>
            <translation>轮廓</translation>
        </message>
        <message>
            <source>cannot write {}: {}</source>
            <translation>无法写入 {}：{}</translation>
        </message>
        <message>
            <source>the file changed while it was read</source>
            <translation>读取过程中文件被更改</translation>
        </message>
        <message>
            <source>cannot create a file in {}: {}</source>
            <translation>无法在 {} 中创建文件：{}</translation>
        </message>
        <message>
            <source>cannot create the lock file {}: {}</source>
            <translation>无法创建锁文件 {}：{}</translation>
        </message>
        <message>
            <source>cannot lock {}: {}</source>
            <translation>无法锁定 {}：{}</translation>
        </message>
        <message>
            <source>a string ({})</source>
            <translation>字符串（{}）</translation>
        </message>
        <message>
            <source>null</source>
            <translation>null</translation>
        </message>
        <message>
            <source>an object</source>
            <translation>对象</translation>
        </message>
        <message>
            <source>an array</source>
            <translation>数组</translation>
        </message>
        <message>
            <source>a string</source>
            <translation>字符串</translation>
        </message>
        <message>
            <source>a boolean</source>
            <translation>布尔值</translation>
        </message>
        <message>
            <source>an unexpected value</source>
            <translation>意外的值</translation>
        </message>
        <message>
            <source>one of {}</source>
            <translation>{} 之一</translation>
        </message>
        <message>
            <source>the file is {} bytes ({:.1f} MB); a job file may be at most {} bytes ({} MB)</source>
            <translation>文件为 {} 字节（{} MB）；作业文件最多 {} 字节（{} MB）</translation>
        </message>
        <message>
            <source>cannot open: {}</source>
            <translation>无法打开：{}</translation>
        </message>
        <message>
            <source>cannot read the file: {}</source>
            <translation>无法读取文件：{}</translation>
        </message>
        <message>
            <source>not a regular file; a job file is a JSON document</source>
            <translation>不是普通文件；作业文件是 JSON 文档</translation>
        </message>
        <message>
            <source>not a job file: JSON syntax error at byte {} (line {}, column {}): {}</source>
            <translation>不是作业文件：第 {} 字节（第 {} 行，第 {} 列）处 JSON 语法错误：{}</translation>
        </message>
        <message>
            <source>not a job file: arrays and objects nested more than {} deep at byte {} (line {}, column {})</source>
            <translation>不是作业文件：第 {1} 字节（第 {2} 行，第 {3} 列）处数组和对象嵌套超过 {0} 层</translation>
        </message>
        <message>
            <source>the number {} is too large for any dimension</source>
            <translation>数字 {} 对任何尺寸都过大</translation>
        </message>
        <message>
            <source>not a job file: the document is {}, a job is a JSON object</source>
            <translation>不是作业文件：文档是{}，作业应为 JSON 对象</translation>
        </message>
        <message>
            <source>not a job file: it has no "format": "taiwa-job"</source>
            <translation>不是作业文件：没有 "format": "taiwa-job"</translation>
        </message>
        <message>
            <source>not a job file: its "format" is {}, a job has "taiwa-job"</source>
            <translation>不是作业文件：其 "format" 为{}，作业应为 "taiwa-job"</translation>
        </message>
        <message>
            <source>written by a newer Taiwa (format version {}); this program reads version {}</source>
            <translation>由较新的 Taiwa 写入（格式版本 {}）；本程序读取版本 {}</translation>
        </message>
        <message>
            <source>format version {} does not exist; this program reads version {}</source>
            <translation>格式版本 {} 不存在；本程序读取版本 {}</translation>
        </message>
        <message>
            <source>missing; it must be {}</source>
            <translation>缺失；必须是{}</translation>
        </message>
        <message>
            <source>must be {}, found {}</source>
            <translation>必须是{}，实际为{}</translation>
        </message>
        <message>
            <source>must be a whole number, found {}</source>
            <translation>必须是整数，实际为{}</translation>
        </message>
        <message>
            <source>must be a whole number from -2147483648 to 2147483647, found {}</source>
            <translation>必须是 -2147483648 到 2147483647 的整数，实际为{}</translation>
        </message>
        <message>
            <source>unknown field; {} has {}</source>
            <translation>未知字段；{}包含 {}</translation>
        </message>
        <message>
            <source>unknown module {}; this program knows {}</source>
            <translation>未知模块 {}；本程序已知 {}</translation>
        </message>
        <message>
            <source>unknown stock shape {}; this program knows {}</source>
            <translation>未知毛坯形状 {}；本程序已知 {}</translation>
        </message>
        <message>
            <source>needs exactly four corner points P1..P4, found {}</source>
            <translation>需要恰好四个角点 P1..P4，实际为 {} 个</translation>
        </message>
        <message>
            <source>must be a point [x, y], found an array of {}</source>
            <translation>必须是点 [x, y]，实际为含 {} 个元素的数组</translation>
        </message>
        <message>
            <source>must be a point [x, y], found {}</source>
            <translation>必须是点 [x, y]，实际为{}</translation>
        </message>
        <message>
            <source>given more than once; say it once so that it is clear which value counts</source>
            <translation>指定了不止一次；请只指定一次，以明确哪个值有效</translation>
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
            <translation>钳口高度</translation>
        </message>
        <message>
            <source>the surface speed S</source>
            <translation>切削速度 S</translation>
        </message>
        <message>
            <source>the spindle speed S</source>
            <translation>主轴转速 S</translation>
        </message>
        <message>
            <source>the feed F</source>
            <translation>进给 F</translation>
        </message>
        <message>
            <source>the follower's dwell is {:g} spindle revolutions; it must be at least 0.5, or the follower cuts where the leader has not</source>
            <translation>跟随刀架的暂停为主轴 {:g} 转；至少须为 0.5 转，否则跟随刀架会切到领先刀架尚未切过的地方</translation>
        </message>
        <message>
            <source>machine {} has one path; the two-path settings are for a two-path lathe ({})</source>
            <translation>机床 {} 只有一个通道；双通道设置用于双通道车床（{}）</translation>
        </message>
        <message>
            <source>M{} is not a wait code of machine {}: it waits with M{} to M{}</source>
            <translation>M{} 不是机床 {} 的等待代码：它的等待代码为 M{} 至 M{}</translation>
        </message>
        <message>
            <source>'{}' is not a work offset: give G54 to G59, G59.1 to G59.3, G54.1 P1 to P48 (G154 P on Haas) or G505 to G599 (SINUMERIK)</source>
            <translation>'{}' 不是工件坐标系: 请给出 G54 至 G59、G59.1 至 G59.3、G54.1 P1 至 P48（Haas 上为 G154 P）或 G505 至 G599（SINUMERIK）</translation>
        </message>
        <message>
            <source>unknown dialect '{}'; this program posts {}</source>
            <translation>未知的数控系统 '{}'；本程序可输出 {}</translation>
        </message>
        <message>
            <source>the {} dialect writes no two-path programs; machine {} needs one of the ISO dialects</source>
            <translation>数控系统 {} 不输出双通道程序；机床 {} 需要 ISO 格式的数控系统之一</translation>
        </message>
        <message>
            <source>an object with S and/or F</source>
            <translation>含 S 和/或 F 的对象</translation>
        </message>
        <message>
            <source>a step's speed and feed</source>
            <translation>工序的转速和进给</translation>
        </message>
        <message>
            <source>give S, F or both</source>
            <translation>请给出 S、F 或两者</translation>
        </message>
        <message>
            <source>a bar stock</source>
            <translation>棒料毛坯</translation>
        </message>
        <message>
            <source>a block stock</source>
            <translation>块料毛坯</translation>
        </message>
        <message>
            <source>an array of lines of figure-element text</source>
            <translation>图形元素文本行的数组</translation>
        </message>
        <message>
            <source>a line of text</source>
            <translation>一行文本</translation>
        </message>
        <message>
            <source>a line of the figure holds a line break; give each line as its own string</source>
            <translation>图形的一行中含有换行符；请将每行作为单独的字符串给出</translation>
        </message>
        <message>
            <source>the clamping</source>
            <translation>装夹</translation>
        </message>
        <message>
            <source>the two-path settings</source>
            <translation>双通道设置</translation>
        </message>
        <message>
            <source>true or false</source>
            <translation>true 或 false</translation>
        </message>
        <message>
            <source>the technology overrides</source>
            <translation>工艺参数覆盖</translation>
        </message>
        <message>
            <source>a job</source>
            <translation>作业</translation>
        </message>
        <message>
            <source>an array of machining units</source>
            <translation>加工单元数组</translation>
        </message>
        <message>
            <source>{} more warnings not listed</source>
            <translation>另有 {} 个警告未列出</translation>
        </message>
        <message>
            <source>{} more errors not listed; correct the ones above first</source>
            <translation>另有 {} 个错误未列出；请先更正上面的错误</translation>
        </message>
        <message>
            <source>pilot hole</source>
            <translation>预钻孔</translation>
        </message>
        <message>
            <source>roughing</source>
            <translation>粗加工</translation>
        </message>
        <message>
            <source>floor finishing</source>
            <translation>底面精加工</translation>
        </message>
        <message>
            <source>wall finishing</source>
            <translation>侧壁精加工</translation>
        </message>
        <message>
            <source>inclined-face finishing</source>
            <translation>斜面精加工</translation>
        </message>
        <message>
            <source>facing</source>
            <translation>车端面</translation>
        </message>
        <message>
            <source>centre drilling</source>
            <translation>中心钻孔</translation>
        </message>
        <message>
            <source>drilling</source>
            <translation>钻孔</translation>
        </message>
        <message>
            <source>grooving</source>
            <translation>切槽</translation>
        </message>
        <message>
            <source>finishing</source>
            <translation>精加工</translation>
        </message>
        <message>
            <source>threading</source>
            <translation>车螺纹</translation>
        </message>
        <message>
            <source>parting off</source>
            <translation>切断</translation>
        </message>
        <message>
            <source>tapping</source>
            <translation>攻丝</translation>
        </message>
        <message>
            <source>reaming</source>
            <translation>铰孔</translation>
        </message>
        <message>
            <source>boring</source>
            <translation>镗孔</translation>
        </message>
        <message>
            <source>face milling</source>
            <translation>面铣</translation>
        </message>
        <message>
            <source>side milling</source>
            <translation>侧铣</translation>
        </message>
        <message>
            <source>area clearing</source>
            <translation>区域加工</translation>
        </message>
        <message>
            <source>the wall allowance roughing leaves</source>
            <translation>粗加工留下的壁余量</translation>
        </message>
        <message>
            <source>the wall allowance semi-finishing leaves</source>
            <translation>半精加工留下的壁余量</translation>
        </message>
        <message>
            <source>the floor allowance roughing leaves</source>
            <translation>粗加工留下的底面余量</translation>
        </message>
        <message>
            <source>centre drill</source>
            <translation>中心钻</translation>
        </message>
        <message>
            <source>drill</source>
            <translation>钻头</translation>
        </message>
        <message>
            <source>flat end mill</source>
            <translation>平底立铣刀</translation>
        </message>
        <message>
            <source>ball end mill</source>
            <translation>球头立铣刀</translation>
        </message>
        <message>
            <source>taper end mill</source>
            <translation>锥度立铣刀</translation>
        </message>
        <message>
            <source>face mill</source>
            <translation>面铣刀</translation>
        </message>
        <message>
            <source>turning insert</source>
            <translation>车削刀片</translation>
        </message>
        <message>
            <source>grooving tool</source>
            <translation>切槽刀</translation>
        </message>
        <message>
            <source>threading tool</source>
            <translation>螺纹车刀</translation>
        </message>
        <message>
            <source>probe</source>
            <translation>测头</translation>
        </message>
        <message>
            <source>tap</source>
            <translation>丝锥</translation>
        </message>
        <message>
            <source>reamer</source>
            <translation>铰刀</translation>
        </message>
        <message>
            <source>boring bar</source>
            <translation>镗杆</translation>
        </message>
        <message>
            <source>a point's X</source>
            <translation>点的 X</translation>
        </message>
        <message>
            <source>a point's Y</source>
            <translation>点的 Y</translation>
        </message>
        <message>
            <source>{} passes along an area of {} lines and arcs are more than the checks take ({:.3g} pass-segment pairs at most); draw fewer points, or simplify the area's contours</source>
            <translation>{} 条路径沿由 {} 条直线和圆弧组成的区域，超出检查所能处理的量（路径与线段的组合最多 {:.3g} 个）；请减少点数，或简化区域轮廓</translation>
        </message>
        <message>
            <source>the {} passes' strips overlap in more than {} pairs: what they leave unswept is more than the checks take; draw fewer passes, or passes that cross each other less</source>
            <translation>{} 条路径的条带重叠超过 {} 对：计算未扫过区域超出检查所能处理的量；请减少路径，或画交叉较少的路径</translation>
        </message>
        <message>
            <source>the tool diameter</source>
            <translation>刀具直径</translation>
        </message>
        <message>
            <source>an array of points [x, y]</source>
            <translation>点 [x, y] 的数组</translation>
        </message>
        <message>
            <source>'{}' is not a list of points; type each point as X, Y and separate the points with ';' (10, 20; 60, 20), or draw the passes in the Figure tab</source>
            <translation>“{}”不是点列表；请将每个点输入为 X, Y，并用 ';' 分隔各点（10, 20; 60, 20），或在图形选项卡中绘制路径</translation>
        </message>
        <message>
            <source>no point is drawn; a pass runs from a start point to an end point: draw at least two points</source>
            <translation>尚未绘制任何点；路径从起点到终点：请至少绘制两个点</translation>
        </message>
        <message>
            <source>only one point is drawn; a pass runs from a start point to an end point: draw at least two points</source>
            <translation>只绘制了一个点；路径从起点到终点：请至少绘制两个点</translation>
        </message>
        <message>
            <source>point {} ({}, {}) lies outside the stock</source>
            <translation>点 {}（{}, {}）位于毛坯之外</translation>
        </message>
        <message>
            <source>pass {} ends where it starts; remove the repeated point</source>
            <translation>路径 {} 的终点与起点相同；请删除重复的点</translation>
        </message>
        <message>
            <source>the start point ({}, {}) puts the tool's edge {} outside the area {} or into an island; start at least a tool radius inside</source>
            <translation>起点（{0}, {1}）使刀具边缘超出区域 {3} 或进入岛屿 {2}；请至少在内侧一个刀具半径处开始</translation>
        </message>
        <message>
            <source>pass {} takes the tool's edge {} outside the area {} (or into an island) with the tool's centre at ({}, {}); keep each pass a tool radius from the walls</source>
            <translation>路径 {0} 在刀具中心位于（{3}, {4}）时使刀具边缘超出区域 {2}（或进入岛屿）{1}；请使每条路径与壁保持一个刀具半径</translation>
        </message>
        <message>
            <source>the tool diameter is {}; it must be positive: the passes are strips one tool wide</source>
            <translation>刀具直径为 {}；必须为正：路径是一个刀具宽的条带</translation>
        </message>
        <message>
            <source>the library has no centre-cutting flat end mill of {} (nor of any diameter) for the drawn passes</source>
            <translation>刀具库中没有用于所绘路径的 {}（或任何直径）的中心切削平底立铣刀</translation>
        </message>
        <message>
            <source>the library has no centre-cutting flat end mill of {}, the width the passes were drawn for; its flat end mills: {}</source>
            <translation>刀具库中没有路径绘制宽度 {} 的中心切削平底立铣刀；已有的平底立铣刀：{}</translation>
        </message>
        <message>
            <source>{} is pinned, but the passes were drawn for a tool of {}; pin a tool of that diameter or change the diameter and redraw</source>
            <translation>已指定 {}，但路径是为 {} 的刀具绘制的；请指定该直径的刀具，或更改直径后重新绘制</translation>
        </message>
        <message>
            <source>the passes leave {} of the area unswept in {} place; the largest, {}, near ({}, {})</source>
            <translation>路径在 {1} 处留下 {0} 的区域未切削；最大的一处为 {2}，位于（{3}, {4}）附近</translation>
        </message>
        <message>
            <source>the passes leave {} of the area unswept in {} places; the largest, {}, near ({}, {})</source>
            <translation>路径在 {1} 处留下 {0} 的区域未切削；最大的一处为 {2}，位于（{3}, {4}）附近</translation>
        </message>
        <message>
            <source>the passes were drawn {} mm wide</source>
            <translation>刀路按 {} mm 宽绘制</translation>
        </message>
        <message>
            <source>pocket</source>
            <translation>型腔</translation>
        </message>
        <message>
            <source>the island {} touches {} at ({}, {}): no end mill passes between them; keep it {} off (the smallest end mill, {}, with what the step leaves on the walls) or make the two one contour</source>
            <translation>岛 {0} 在 ({2}, {3}) 处与 {1} 相接：没有立铣刀能从两者之间通过；请使其离开至少 {4}（最小的立铣刀 {5} 加上工步在壁上留下的余量），或将两者合为一个轮廓</translation>
        </message>
        <message>
            <source>the gap between the island {} and {} is {} wide at ({}, {}); the smallest end mill, {}, needs {} there</source>
            <translation>岛 {0} 与 {1} 之间的间隙在 ({3}, {4}) 处宽 {2}；最小的立铣刀 {5} 在该处需要 {6}</translation>
        </message>
        <message>
            <source>{} narrows to {} between ({}, {}) and ({}, {}); the smallest end mill, {}, needs {} there</source>
            <translation>{0} 在 ({2}, {3}) 与 ({4}, {5}) 之间收窄到 {1}；最小的立铣刀 {6} 在该处需要 {7}</translation>
        </message>
        <message>
            <source>{} has an inside arc of radius {} at ({}, {}); the smallest end mill, {}, needs a radius of at least {} there</source>
            <translation>{0} 在 ({2}, {3}) 处有半径为 {1} 的内侧圆弧；最小的立铣刀 {4} 在该处需要至少 {5} 的半径</translation>
        </message>
        <message>
            <source>the contour's narrowest reach</source>
            <translation>轮廓最窄处</translation>
        </message>
        <message>
            <source>{} has an inside arc of radius {} at ({}, {}): the end mills that fit it have flutes shorter than the depth {} (the longest-fluted, {}); {} reaches that depth but needs a radius of {} there, {} more (make the arc larger, or the pocket shallower)</source>
            <translation>{0} 在 ({2}, {3}) 处有半径为 {1} 的内侧圆弧：能进入该处的立铣刀刃长都短于深度 {4}（刃长最长的是 {5}）；能达到该深度的 {6} 在该处需要 {7} 的半径，还差 {8}（请加大圆弧，或把型腔改浅）</translation>
        </message>
        <message>
            <source>{} narrows to {} between ({}, {}) and ({}, {}): the end mills that pass there have flutes shorter than the depth {} (the longest-fluted, {}); {} reaches that depth but needs it {} wider there (widen it, or make the pocket shallower)</source>
            <translation>{0} 在 ({2}, {3}) 与 ({4}, {5}) 之间收窄到 {1}：能通过该处的立铣刀刃长都短于深度 {6}（刃长最长的是 {7}）；能达到该深度的 {8} 需要该处再宽 {9}（请加宽该处，或把型腔改浅）</translation>
        </message>
        <message>
            <source>the gap between the island {} and {} is {} wide at ({}, {}): the end mills that pass there have flutes shorter than the depth {} (the longest-fluted, {}); {} reaches that depth but needs {} there, {} more (widen the gap, or make the pocket shallower)</source>
            <translation>岛 {0} 与 {1} 之间的间隙在 ({3}, {4}) 处宽 {2}：能通过该处的立铣刀刃长都短于深度 {5}（刃长最长的是 {6}）；能达到该深度的 {7} 在该处需要 {8}，还差 {9}（请加宽间隙，或把型腔改浅）</translation>
        </message>
        <message>
            <source>U {} is not a tool use of face milling; give 1 (roughing layers and a finishing pass) or 9 (roughing only, the finishing allowance left)</source>
            <translation>U {} 不是面铣的刀具使用方式；请给出 1（粗加工层和精加工刀路）或 9（仅粗加工，留精加工余量）</translation>
        </message>
        <message>
            <source>pattern {} is not a face-milling pattern; give 1 (one way, climb: every pass in the same direction) or 2 (zigzag: back and forth)</source>
            <translation>模式 {} 不是面铣模式；请给出 1（单向顺铣：每条刀路同一方向）或 2（之字形：往复）</translation>
        </message>
        <message>
            <source>the depth</source>
            <translation>深度</translation>
        </message>
        <message>
            <source>the depth {} is not less than the stock's height {}: facing takes a layer off the top, it does not mill the whole block away</source>
            <translation>深度 {} 不小于毛坯高度 {}：面铣只切除顶部一层，而不是把整块铣掉</translation>
        </message>
        <message>
            <source>the finishing pass</source>
            <translation>精加工量</translation>
        </message>
        <message>
            <source>the finishing pass is {}; it must be greater than zero (leave the field empty for the technology data's β2)</source>
            <translation>精加工量为 {}；必须大于零（留空则使用工艺数据的 β2）</translation>
        </message>
        <message>
            <source>the finishing pass {}{} is not less than the depth {}: roughing would have nothing to take; give a smaller finishing pass</source>
            <translation>精加工量 {}{} 不小于深度 {}：粗加工将无料可切；请给出更小的精加工量</translation>
        </message>
        <message>
            <source>the angle</source>
            <translation>角度</translation>
        </message>
        <message>
            <source>the angle {} lies beyond ±360°; give the passes' direction from +X, e.g. 0 or 90</source>
            <translation>角度 {} 超出 ±360°；请给出从 +X 起算的刀路方向，例如 0 或 90</translation>
        </message>
        <message>
            <source>the step-over {:g} × D must be greater than 0: passes that do not step sideways never cover the face</source>
            <translation>行距 {} × D 必须大于 0：不横向移动的刀路永远覆盖不了整个面</translation>
        </message>
        <message>
            <source>the step-over {:g} × D is less than {:g} × D: the face would take more than a hundred passes a tool diameter</source>
            <translation>行距 {} × D 小于 {} × D：每个刀具直径将需要一百多条刀路</translation>
        </message>
        <message>
            <source>the step-over {:g} × D is more than {:g} × D: neighbouring passes would overlap by less than a tenth of the diameter, and the inserts' corners and the tool's run-out leave ridges between them</source>
            <translation>行距 {} × D 大于 {} × D：相邻刀路重叠不到直径的十分之一，刀片角和刀具跳动会在其间留下凸棱</translation>
        </message>
        <message>
            <source>the margin</source>
            <translation>外延量</translation>
        </message>
        <message>
            <source>the margin is {}; it must be 0 (the face is the stock's top) or more (the face reaches beyond the stock's sides): less would leave the top's edges unfaced</source>
            <translation>外延量为 {}；必须为 0（面即毛坯顶面）或更大（面超出毛坯侧面）：更小会使顶面边缘未被铣削</translation>
        </message>
        <message>
            <source>{} is pinned for "face" but is not a face mill or a flat end mill: a face is cut flat by the tool's flat bottom</source>
            <translation>{} 被指定用于 "face"，但不是面铣刀或平底立铣刀：平面由刀具的平底切出</translation>
        </message>
        <message>
            <source>{} is pinned for "face" but is not a face mill or a flat end mill with a corner radius under 0.4 D: a face is cut flat by the tool's flat bottom</source>
            <translation>{} 被指定用于 "face"，但不是面铣刀或圆角半径小于 0.4 D 的平底立铣刀：平面由刀具的平底切出</translation>
        </message>
        <message>
            <source>{} is pinned for "face" but cuts {} at most, less than the finishing pass {}; give a smaller finishing pass or another tool</source>
            <translation>{} 被指定用于 "face"，但最多切削 {}，小于精加工量 {}；请给出更小的精加工量或换一把刀具</translation>
        </message>
        <message>
            <source>the tool library has no face mill or flat end mill that cuts the finishing pass {} in one cut; add one or give a smaller finishing pass</source>
            <translation>刀具库中没有能一刀切出精加工量 {} 的面铣刀或平底立铣刀；请添加一把或给出更小的精加工量</translation>
        </message>
        <message>
            <source>largest {} in the library (Ø{}), cutting {} a layer</source>
            <translation>刀具库中最大的{}（Ø{}），每层切削 {}</translation>
        </message>
        <message>
            <source>{} {} must be 1 to {}</source>
            <translation>{} {} 必须为 1 到 {}</translation>
        </message>
        <message>
            <source>the columns</source>
            <translation>列数</translation>
        </message>
        <message>
            <source>the number of holes</source>
            <translation>孔数</translation>
        </message>
        <message>
            <source>the rows</source>
            <translation>行数</translation>
        </message>
        <message>
            <source>{} columns by {} rows are {} holes, more than the {} a unit may have</source>
            <translation>{} 列 × {} 行共 {} 个孔，超过单元上限 {} 个</translation>
        </message>
        <message>
            <source>the angle {} must be from -360° to 360°</source>
            <translation>角度 {} 必须在 -360° 到 360° 之间</translation>
        </message>
        <message>
            <source>{} {} must be greater than zero</source>
            <translation>{} {} 必须大于零</translation>
        </message>
        <message>
            <source>the pitch</source>
            <translation>间距</translation>
        </message>
        <message>
            <source>the pitch between rows</source>
            <translation>行间距</translation>
        </message>
        <message>
            <source>the angular pitch {:g}° must not be 0 and lie within ±360°</source>
            <translation>角度间距 {}° 不能为 0 且必须在 ±360° 以内</translation>
        </message>
        <message>
            <source>thread "{}" is not one this program taps: ISO metric coarse {}</source>
            <translation>螺纹“{}”不是本程序可攻的螺纹：ISO 公制粗牙 {}</translation>
        </message>
        <message>
            <source>a tapped hole's diameter is its thread's: leave out "diameter"</source>
            <translation>螺纹孔的直径即其螺纹的直径：请省略 "diameter"</translation>
        </message>
        <message>
            <source>the diameter</source>
            <translation>直径</translation>
        </message>
        <message>
            <source>the diameter {} must be {} to {}</source>
            <translation>直径 {} 必须为 {} 到 {}</translation>
        </message>
        <message>
            <source>the depth {} must be greater than zero</source>
            <translation>深度 {} 必须大于零</translation>
        </message>
        <message>
            <source>{} {} is not more than the hole's diameter {}: the holes would cut into each other</source>
            <translation>{} {} 不大于孔径 {}：孔会相互切入</translation>
        </message>
        <message>
            <source>the distance between neighbouring holes</source>
            <translation>相邻孔的间距</translation>
        </message>
        <message>
            <source>holes {} and {} lie {} apart, not more than the diameter {}: the arc closes on itself; fewer holes or a smaller angular pitch</source>
            <translation>孔 {} 和 {} 相距 {}，不大于直径 {}：圆弧首尾相接；请减少孔数或减小角度间距</translation>
        </message>
        <message>
            <source>hole {} (X {}, Y {}) reaches outside the stock; move the pattern or enlarge the stock</source>
            <translation>孔 {}（X {}, Y {}）超出毛坯；请移动孔阵列或加大毛坯</translation>
        </message>
        <message>
            <source>the hole goes down to {} with its drill point (its tools go deeper than the depth {}; docs/holes.md), below the stock's height {}: through holes are not made; make it shallower</source>
            <translation>孔连同钻尖深达 {}（刀具比深度 {} 更深；docs/holes.md），低于毛坯高度 {}：不加工通孔；请减小深度</translation>
        </message>
        <message>
            <source>a {} hole has no step "{}"; its steps are {}</source>
            <translation>{}孔没有工序“{}”；其工序为 {}</translation>
        </message>
        <message>
            <source>pattern "{}" is not one of {}</source>
            <translation>孔阵列“{}”不是 {} 之一</translation>
        </message>
        <message>
            <source>hole "{}" is not one of {}</source>
            <translation>孔“{}”不是 {} 之一</translation>
        </message>
        <message>
            <source>T{} ({}) is pinned for "{}" but is not a {}</source>
            <translation>T{}（{}）被指定用于“{}”，但不是{}</translation>
        </message>
        <message>
            <source>no {} in the tool library; add one</source>
            <translation>刀具库中没有{}；请添加一把</translation>
        </message>
        <message>
            <source>the tap drill of {}</source>
            <translation>{} 的底孔钻头</translation>
        </message>
        <message>
            <source>the hole's</source>
            <translation>孔的</translation>
        </message>
        <message>
            <source>drill of Ø{} ({}) whose flutes reach {}</source>
            <translation>Ø{} 钻头（{}），刃长达 {}</translation>
        </message>
        <message>
            <source>drill of Ø{}: {}</source>
            <translation>Ø{} 钻头：{}</translation>
        </message>
        <message>
            <source>drill from Ø{} to Ø{} (to {} Ø{}: {} to {} under) whose flutes reach {}</source>
            <translation>Ø{} 到 Ø{} 的钻头（相对{} Ø{} 小 {} 到 {}），刃长达 {}</translation>
        </message>
        <message>
            <source>ream</source>
            <translation>铰孔</translation>
        </message>
        <message>
            <source>bore</source>
            <translation>镗孔</translation>
        </message>
        <message>
            <source>largest drill {} to {} under Ø{} to {}</source>
            <translation>比 Ø{2} 小 {0} 到 {1} 的最大钻头（用于{3}）</translation>
        </message>
        <message>
            <source>tap {}x{:g} (type tap, Ø{}, pitch {}) whose flutes reach {}</source>
            <translation>丝锥 {}x{}（类型 tap，Ø{}，螺距 {}），刃长达 {}</translation>
        </message>
        <message>
            <source>tap {}x{:g}</source>
            <translation>丝锥 {}x{}</translation>
        </message>
        <message>
            <source>{} of Ø{} whose flutes reach {}</source>
            <translation>Ø{1} 的{0}，刃长达 {2}</translation>
        </message>
        <message>
            <source>boring bar (set to the bore)</source>
            <translation>镗杆（调至孔径）</translation>
        </message>
        <message>
            <source>{} of the hole's Ø{}</source>
            <translation>孔径 Ø{1} 的{0}</translation>
        </message>
        <message>
            <source>boring tool</source>
            <translation>镗刀</translation>
        </message>
        <message>
            <source>centre drill spotting Ø{} for the Ø{} drill</source>
            <translation>为 Ø{1} 钻头点出 Ø{0} 的中心钻</translation>
        </message>
        <message>
            <source>the corner radius</source>
            <translation>圆角半径</translation>
        </message>
        <message>
            <source>the scallop height</source>
            <translation>残留高度</translation>
        </message>
        <message>
            <source>pocket opening</source>
            <translation>型腔开口</translation>
        </message>
        <message>
            <source>roughing layers</source>
            <translation>粗加工各层</translation>
        </message>
        <message>
            <source>the scallop height is {}; it must be at least {} (a smaller one multiplies the passes of the inclined faces without a finer surface any machine holds)</source>
            <translation>残留高度为 {}；至少应为 {}（更小只会使斜面刀路成倍增加，而机床无法保持更精细的表面）</translation>
        </message>
        <message>
            <source>the corner radius {} is larger than half of L2 = {}</source>
            <translation>圆角半径 {} 大于 L2 = {} 的一半</translation>
        </message>
        <message>
            <source>{} = {} is outside 0° to under 60° (measured from the vertical)</source>
            <translation>{} = {} 超出 0° 到小于 60° 的范围（自竖直方向测量）</translation>
        </message>
        <message>
            <source>the inclined walls leave a floor {} wide along L1; it must be wider than 2 × r1 = {} (short by {}): reduce the angles or the depth, or lengthen L1</source>
            <translation>倾斜壁使沿 L1 方向的底面宽度为 {}；必须宽于 2 × r1 = {}（差 {}）：请减小角度或深度，或加长 L1</translation>
        </message>
        <message>
            <source>the scallop height is {}; it must be greater than zero (usual 0.01 mm)</source>
            <translation>残留高度为 {}；必须大于零（通常 0.01 mm）</translation>
        </message>
        <message>
            <source>tool-use code U = {} is not allowed for M2D; use 1 (rough and finish) or 9 (rough only)</source>
            <translation>刀具使用代码 U = {} 不可用于 M2D；请使用 1（粗加工和精加工）或 9（仅粗加工）</translation>
        </message>
        <message>
            <source>the coordinate X of {}</source>
            <translation>{} 的 X 坐标</translation>
        </message>
        <message>
            <source>the coordinate Y of {}</source>
            <translation>{} 的 Y 坐标</translation>
        </message>
        <message>
            <source>the cornerRadius</source>
            <translation>圆角半径</translation>
        </message>
        <message>
            <source>the taper</source>
            <translation>锥度</translation>
        </message>
        <message>
            <source>an array of 4 points [x, y]</source>
            <translation>4 个点 [x, y] 的数组</translation>
        </message>
        <message>
            <source>the final wall allowance α3 = {} must be smaller than the roughing wall allowance α2 = {}</source>
            <translation>壁最终精加工余量 α3 = {} 必须小于粗加工壁余量 α2 = {}</translation>
        </message>
        <message>
            <source>P{} and P{} are the same point ({}, {}); the outline needs four distinct corners</source>
            <translation>P{} 和 P{} 是同一点（{}, {}）；轮廓需要四个不同的角点</translation>
        </message>
        <message>
            <source>the outline crosses itself; enter the corners P1..P4 in order around the pocket</source>
            <translation>外轮廓自相交；请沿型腔依次输入角点 P1..P4</translation>
        </message>
        <message>
            <source>the outline is not convex (a corner points inward or three corners are in line)</source>
            <translation>外轮廓不是凸的（有角点朝内，或三个角点共线）</translation>
        </message>
        <message>
            <source>the corner radius {} is larger than half the shortest side ({} long)</source>
            <translation>圆角半径 {} 大于最短边（长 {}）的一半</translation>
        </message>
        <message>
            <source>the corner radius {} does not fit: the largest circle inside the outline has radius {}</source>
            <translation>圆角半径 {} 放不下：外轮廓内最大圆的半径为 {}</translation>
        </message>
        <message>
            <source>the taper {} per side is outside 0° to 30°</source>
            <translation>单边锥度 {} 超出 0° 到 30° 的范围</translation>
        </message>
        <message>
            <source>with a taper of {} per side the walls meet at depth {}, above the floor</source>
            <translation>单边锥度为 {} 时，两壁在底面以上的深度 {} 处相交</translation>
        </message>
        <message>
            <source>an array of contour names</source>
            <translation>轮廓名数组</translation>
        </message>
        <message>
            <source>a contour name</source>
            <translation>轮廓名</translation>
        </message>
        <message>
            <source>outline</source>
            <translation>外轮廓</translation>
        </message>
        <message>
            <source>{} islands; a {} may have at most {} (the checks compare every two of them)</source>
            <translation>{} 个岛；{}最多可有 {} 个（检查会两两比较）</translation>
        </message>
        <message>
            <source>the {}'s outline {} and its islands have {} lines and arcs; at most {} are taken (simplify the contours, or join short lines into arcs)</source>
            <translation>{}的轮廓 {} 及其岛共有 {} 条直线和圆弧；最多 {} 条（请简化轮廓，或将短线合并为圆弧）</translation>
        </message>
        <message>
            <source>island</source>
            <translation>岛屿</translation>
        </message>
        <message>
            <source>tool-use code U = {} is not defined (codes 2 to 5 are reserved); use 1, 6, 7, 8 or 9</source>
            <translation>刀具使用代码 U = {} 未定义（代码 2 到 5 为保留）；请使用 1、6、7、8 或 9</translation>
        </message>
        <message>
            <source>tool-use code U = {} does not exist; use 1, 6, 7, 8 or 9</source>
            <translation>刀具使用代码 U = {} 不存在；请使用 1、6、7、8 或 9</translation>
        </message>
        <message>
            <source>finishing code F = {} does not exist; use 1, 2 or 3</source>
            <translation>精加工代码 F = {} 不存在；请使用 1、2 或 3</translation>
        </message>
        <message>
            <source>pilot-hole code H = {} does not exist; use 0 (drill a pilot hole) or 9 (none)</source>
            <translation>预钻孔代码 H = {} 不存在；请使用 0（钻预钻孔）或 9（无）</translation>
        </message>
        <message>
            <source>the corner radius is {}; it cannot be negative</source>
            <translation>圆角半径为 {}；不能为负</translation>
        </message>
        <message>
            <source>U {} is not offered for contour pockets; use 1 (all steps), 6 (no wall finishing), 8 (walls only) or 9 (roughing only)</source>
            <translation>U {} 不适用于轮廓型腔；请使用 1（全部工序）、6（无壁精加工）、8（仅壁）或 9（仅粗加工）</translation>
        </message>
        <message>
            <source>largest {} ({}) whose radius {} fits the corner radius {} of the {}</source>
            <translation>用于{4}的、半径 {2} 适合圆角半径 {3} 的最大{0}（{1}）</translation>
        </message>
        <message>
            <source>largest {} ({}) of diameter at most half the pocket's inscribed width {} of the {}</source>
            <translation>用于{3}的、直径不超过型腔内切宽度 {2} 一半的最大{0}（{1}）</translation>
        </message>
        <message>
            <source>largest {} ({}) of diameter at most half the pocket's inscribed width {}</source>
            <translation>直径不超过型腔内切宽度 {2} 一半的最大{0}（{1}）</translation>
        </message>
        <message>
            <source>largest {} ({}) of diameter at most half the pocket's inscribed width {}; it cuts at its centre and ramps in (no pilot hole)</source>
            <translation>直径不超过型腔内切宽度 {2} 一半的最大{0}（{1}）；可中心切削，斜向下刀（无预钻孔）</translation>
        </message>
        <message>
            <source>largest {} ({}) of diameter at most half the pocket's inscribed width {}; enters the {} pilot hole</source>
            <translation>直径不超过型腔内切宽度 {2} 一半的最大{0}（{1}）；从 {3} 预钻孔进入</translation>
        </message>
        <message>
            <source>largest {} ({}) of diameter at most half the pocket's inscribed width {}; its flutes ({}) are shorter than the depth {}, as are those of every end mill that fits: it cuts one layer at a time</source>
            <translation>直径不超过型腔内切宽度 {2} 一半的最大{0}（{1}）；其刃长（{3}）短于深度 {4}，所有适用的立铣刀都如此：逐层切削</translation>
        </message>
        <message>
            <source>largest {} ({}) of diameter at most half the pocket's inscribed width {}; its flutes ({}) are shorter than the depth {}, as are those of every end mill that fits: it cuts one layer at a time; it cuts at its centre and ramps in (no pilot hole)</source>
            <translation>直径不超过型腔内切宽度 {2} 一半的最大{0}（{1}）；其刃长（{3}）短于深度 {4}，所有适用的立铣刀都如此：逐层切削；可中心切削，斜向下刀（无预钻孔）</translation>
        </message>
        <message>
            <source>largest {} ({}) of diameter at most half the pocket's inscribed width {}; its flutes ({}) are shorter than the depth {}, as are those of every end mill that fits: it cuts one layer at a time; enters the {} pilot hole</source>
            <translation>直径不超过型腔内切宽度 {2} 一半的最大{0}（{1}）；其刃长（{3}）短于深度 {4}，所有适用的立铣刀都如此：逐层切削；从 {5} 预钻孔进入</translation>
        </message>
        <message>
            <source>largest {} ({}) whose radius {} fits the corner radius {}</source>
            <translation>半径 {2} 适合圆角半径 {3} 的最大{0}（{1}）</translation>
        </message>
        <message>
            <source>largest {} ({}) whose radius {} fits the corner radius {}; it cuts at its centre and ramps in (no pilot hole)</source>
            <translation>半径 {2} 适合圆角半径 {3} 的最大{0}（{1}）；可中心切削，斜向下刀（无预钻孔）</translation>
        </message>
        <message>
            <source>largest {} ({}) whose radius {} fits the corner radius {}; enters the {} pilot hole</source>
            <translation>半径 {2} 适合圆角半径 {3} 的最大{0}（{1}）；从 {4} 预钻孔进入</translation>
        </message>
        <message>
            <source>largest {} ({}) whose radius {} fits the corner radius {}; its flutes ({}) are shorter than the depth {}, as are those of every end mill that fits: it cuts one layer at a time</source>
            <translation>半径 {2} 适合圆角半径 {3} 的最大{0}（{1}）；其刃长（{4}）短于深度 {5}，所有适用的立铣刀都如此：逐层切削</translation>
        </message>
        <message>
            <source>largest {} ({}) whose radius {} fits the corner radius {}; its flutes ({}) are shorter than the depth {}, as are those of every end mill that fits: it cuts one layer at a time; it cuts at its centre and ramps in (no pilot hole)</source>
            <translation>半径 {2} 适合圆角半径 {3} 的最大{0}（{1}）；其刃长（{4}）短于深度 {5}，所有适用的立铣刀都如此：逐层切削；可中心切削，斜向下刀（无预钻孔）</translation>
        </message>
        <message>
            <source>largest {} ({}) whose radius {} fits the corner radius {}; its flutes ({}) are shorter than the depth {}, as are those of every end mill that fits: it cuts one layer at a time; enters the {} pilot hole</source>
            <translation>半径 {2} 适合圆角半径 {3} 的最大{0}（{1}）；其刃长（{4}）短于深度 {5}，所有适用的立铣刀都如此：逐层切削；从 {6} 预钻孔进入</translation>
        </message>
        <message>
            <source>taper end mill of the wall's taper {:g} deg per side (tip {}) whose tip radius {} fits the corner radius {} at the floor</source>
            <translation>与侧壁锥度单边 {0} 度相同的锥度立铣刀（刀尖 {1}），刀尖半径 {2} 适合底部圆角半径 {3}</translation>
        </message>
        <message>
            <source>largest ball end mill ({}) of radius at most 6 mm and half the inclined face's length {}</source>
            <translation>半径不超过 6 mm 且不超过斜面长度 {1} 一半的最大球头立铣刀（{0}）</translation>
        </message>
        <message>
            <source>{}: pinned tool T{} is not in the tool library</source>
            <translation>{}：指定的刀具 T{} 不在刀具库中</translation>
        </message>
        <message>
            <source>{}: pinned tool T{} ({}) does not fit: {}</source>
            <translation>{}：指定的刀具 T{}（{}）不适用：{}</translation>
        </message>
        <message>
            <source>pinned by the operator</source>
            <translation>由操作员指定</translation>
        </message>
        <message>
            <source>smallest drill ({}) not smaller than the {} end mill that plunges into it</source>
            <translation>不小于由此下刀的 {1} 立铣刀的最小钻头（{0}）</translation>
        </message>
        <message>
            <source>shape {} is not defined: 1 round (boss or bore), 2 rectangular (block or pocket)</source>
            <translation>形状 {} 未定义：1 圆形（凸台或孔），2 矩形（块或型腔）</translation>
        </message>
        <message>
            <source>where {} is not defined: 1 touched from outside (boss, block), 2 from inside (bore, pocket)</source>
            <translation>测量侧 {} 未定义：1 从外侧触碰（凸台、块），2 从内侧（孔、型腔）</translation>
        </message>
        <message>
            <source>the X of {}</source>
            <translation>{} 的 X</translation>
        </message>
        <message>
            <source>the Y of {}</source>
            <translation>{} 的 Y</translation>
        </message>
        <message>
            <source>point {}: its {} is missing</source>
            <translation>点 {}：缺少 {}</translation>
        </message>
        <message>
            <source>point {}: say which side it touches: 1 -X, 2 +X, 3 -Y, 4 +Y</source>
            <translation>点 {}：请指定触碰哪一面：1 -X，2 +X，3 -Y，4 +Y</translation>
        </message>
        <message>
            <source>point 1 is the measuring origin: it is at 0, 0 and the others are measured from it</source>
            <translation>点 1 是测量原点：位于 0, 0，其他点均从它测量</translation>
        </message>
        <message>
            <source>the machine Z of the top face</source>
            <translation>顶面的机床 Z 坐标</translation>
        </message>
        <message>
            <source>{} must be above 0 and at most {:g} mm, not {:g}</source>
            <translation>{} 必须大于 0 且不超过 {} mm，而不是 {}</translation>
        </message>
        <message>
            <source>the nominal width along X</source>
            <translation>沿 X 的公称宽度</translation>
        </message>
        <message>
            <source>the nominal diameter</source>
            <translation>公称直径</translation>
        </message>
        <message>
            <source>the nominal length along Y</source>
            <translation>沿 Y 的公称长度</translation>
        </message>
        <message>
            <source>the depth of the side touches</source>
            <translation>侧面触碰深度</translation>
        </message>
        <message>
            <source>the clearance</source>
            <translation>间隙</translation>
        </message>
        <message>
            <source>the search distance</source>
            <translation>搜索距离</translation>
        </message>
        <message>
            <source>the probing feed must be above 0 and at most 5000 mm/min, not {:g}</source>
            <translation>测量进给必须大于 0 且不超过 5000 mm/min，而不是 {}</translation>
        </message>
        <message>
            <source>the tolerance must lie between 0.001 and 1 mm, not {:g}</source>
            <translation>公差必须在 0.001 到 1 mm 之间，而不是 {}</translation>
        </message>
        <message>
            <source>T{} is not a probe in the tool library</source>
            <translation>T{} 不是刀具库中的测头</translation>
        </message>
        <message>
            <source>the tool library has no probe, or several: add one of type "probe" or say which (T)</source>
            <translation>刀具库中没有测头或有多个：请添加一个类型为 "probe" 的测头，或指定使用哪一个（T）</translation>
        </message>
        <message>
            <source>point {} coincides with point {}: touch the outline elsewhere</source>
            <translation>点 {} 与点 {} 重合：请在轮廓的其他位置触碰</translation>
        </message>
        <message>
            <source>point {} is {} off the fitted {} (tolerance {}): touch it again, or check the shape and the order of the points</source>
            <translation>点 {0} 偏离拟合的{2} {1}（公差 {3}）：请重新触碰，或检查形状和点的顺序</translation>
        </message>
        <message>
            <source>a round workpiece needs at least 3 touch points, {} given</source>
            <translation>圆形工件至少需要 3 个触碰点，当前为 {} 个</translation>
        </message>
        <message>
            <source>point {} lies on the line of points 1 to {} (within {}): a circle needs touches spread around it</source>
            <translation>点 {0} 位于点 1 至 {1} 的直线上（{2} 以内）：圆需要分布在四周的触碰点</translation>
        </message>
        <message>
            <source>circle</source>
            <translation>圆</translation>
        </message>
        <message>
            <source>the touches lie on a circle of radius {}, no larger than the stylus ball's radius {}: is the workpiece a bore rather than a boss?</source>
            <translation>触碰点位于半径 {} 的圆上，不大于测球半径 {}：工件是否是孔而不是凸台？</translation>
        </message>
        <message>
            <source>point {}: the side it touches is not given</source>
            <translation>点 {}：未给出其触碰的面</translation>
        </message>
        <message>
            <source>a rectangular workpiece needs a touch on every side: none on {}</source>
            <translation>矩形工件每个面都需要触碰：{} 面没有</translation>
        </message>
        <message>
            <source>the points on -X and +X are swapped: the +X side (point {}) lies at or left of the -X side (point {})</source>
            <translation>-X 与 +X 的点颠倒了：+X 面（点 {}）位于 -X 面（点 {}）处或其左侧</translation>
        </message>
        <message>
            <source>the points on -Y and +Y are swapped: the +Y side (point {}) lies at or below the -Y side (point {})</source>
            <translation>-Y 与 +Y 的点颠倒了：+Y 面（点 {}）位于 -Y 面（点 {}）处或其下方</translation>
        </message>
        <message>
            <source>rectangle</source>
            <translation>矩形</translation>
        </message>
        <message>
            <source>the touches span {} x {}, no more than the stylus ball: is the workpiece a pocket rather than a block?</source>
            <translation>触碰点范围为 {} x {}，不大于测球：工件是否是型腔而不是块？</translation>
        </message>
        <message>
            <source>an array of 1 to 8 points [x, y], the first [0, 0]</source>
            <translation>1 到 8 个点 [x, y] 的数组，第一个为 [0, 0]</translation>
        </message>
        <message>
            <source>a point [x, y] or null</source>
            <translation>点 [x, y] 或 null</translation>
        </message>
        <message>
            <source>an array of up to 8 side codes (1 -X, 2 +X, 3 -Y, 4 +Y)</source>
            <translation>最多 8 个面代码的数组（1 -X，2 +X，3 -Y，4 +Y）</translation>
        </message>
        <message>
            <source>No probe in the tool library (type "probe"): the ball radius is unknown</source>
            <translation>刀具库中没有测头（类型 "probe"）：测球半径未知</translation>
        </message>
        <message>
            <source>{} of at least {} touches entered: the probing cycle the export writes makes them on the machine</source>
            <translation>已输入 {} 个测点（至少 {} 个）：导出的测量循环将在机床上测量</translation>
        </message>
        <message>
            <source>Bore: diameter {}</source>
            <translation>孔：直径 {}</translation>
        </message>
        <message>
            <source>Boss: diameter {}</source>
            <translation>凸台：直径 {}</translation>
        </message>
        <message>
            <source>(not measured: touch one side twice)</source>
            <translation>（未测量：请在同一面测两次）</translation>
        </message>
        <message>
            <source>Pocket: {} x {}, turned {}</source>
            <translation>型腔：{} x {}，转角 {}</translation>
        </message>
        <message>
            <source>Block: {} x {}, turned {}</source>
            <translation>块：{} x {}，转角 {}</translation>
        </message>
        <message>
            <source>Centre from P1: X {} Y {}</source>
            <translation>相对 P1 的中心：X {} Y {}</translation>
        </message>
        <message>
            <source>Work offset to set: X {} Y {} Z {}</source>
            <translation>要设定的工件坐标偏置：X {} Y {} Z {}</translation>
        </message>
        <message>
            <source>Work offset to set: X {} Y {}</source>
            <translation>要设定的工件坐标偏置：X {} Y {}</translation>
        </message>
        <message>
            <source>the {} reaches outside the stock; move it or enlarge the stock</source>
            <translation>{}超出了毛坯；请移动它或加大毛坯</translation>
        </message>
        <message>
            <source>name the contour of the pocket's {} (a CONTOUR of the job's figure elements)</source>
            <translation>请指定型腔{}的轮廓（作业图形元素中的 CONTOUR）</translation>
        </message>
        <message>
            <source>{} is not a contour of the job's figure elements, which define no contour</source>
            <translation>{} 不是作业图形元素中的轮廓（图形元素未定义任何轮廓）</translation>
        </message>
        <message>
            <source>{} is not a contour of the job's figure elements (its contours: {})</source>
            <translation>{} 不是作业图形元素中的轮廓（已有轮廓：{}）</translation>
        </message>
        <message>
            <source>{} is an open contour; an {}'s {} must be closed (a contour without a start and end point)</source>
            <translation>{0} 是开放轮廓；{1}的{2}必须闭合（没有起点和终点的轮廓）</translation>
        </message>
        <message>
            <source>{} is an open contour; a {}'s {} must be closed (a contour without a start and end point)</source>
            <translation>{0} 是开放轮廓；{1}的{2}必须闭合（没有起点和终点的轮廓）</translation>
        </message>
        <message>
            <source>{} crosses itself; check the order of its elements and the side chosen at each junction</source>
            <translation>{} 自相交；请检查其元素顺序以及每个连接处选择的一侧</translation>
        </message>
        <message>
            <source>the island {} reaches outside the {}'s outline {}</source>
            <translation>岛屿 {0} 超出了{1}的外轮廓 {2}</translation>
        </message>
        <message>
            <source>the islands {} and {} overlap; make them one contour</source>
            <translation>岛屿 {} 和 {} 重叠；请将它们合并为一个轮廓</translation>
        </message>
        <message>
            <source>{} has a sharp inside corner at ({}, {}): an end mill cannot cut it and leaves its own radius there; round the corner (ROUND) in the contour</source>
            <translation>{} 在（{}, {}）处有尖锐内角：立铣刀无法切出，会在那里留下自身半径；请在轮廓中将该角倒圆（ROUND）</translation>
        </message>
        <message>
            <source>the width</source>
            <translation>宽度</translation>
        </message>
        <message>
            <source>the width W</source>
            <translation>宽度 W</translation>
        </message>
        <message>
            <source>the contour's smallest inside radius on the tool's side</source>
            <translation>刀具一侧轮廓的最小内侧半径</translation>
        </message>
        <message>
            <source>pinned tool T{} ({}) does not fit: {}</source>
            <translation>指定的刀具 T{}（{}）不合适：{}</translation>
        </message>
        <message>
            <source>no end mill that fits {} reaches the depth {} with its flutes for the finishing at full depth (F 1): the longest, {}, has flutes of {}; finish in several incisions (F 2)</source>
            <translation>能进入 {0} 的立铣刀中，没有刃长能达到深度 {1} 以进行全深度一次精加工（F 1）的：最长的 {2} 刃长为 {3}；请分多次切入精加工（F 2）</translation>
        </message>
        <message>
            <source>{} leaves no room near ({}, {}): even the smallest end mill that fits its arcs, {}, would cut {} into it there; widen the contour there</source>
            <translation>{0} 在 ({1}, {2}) 附近没有余地：即使是能进入其圆弧的最小立铣刀 {3} 也会在该处切入 {4}；请在该处加宽轮廓</translation>
        </message>
        <message>
            <source>{} along {}</source>
            <translation>{}（沿 {}）</translation>
        </message>
        <message>
            <source>largest flat end mill ({}) whose radius {} fits the contour's smallest inside radius {} and whose passes keep off the contour; its flutes ({}) are shorter than T: it cuts in layers</source>
            <translation>半径 {1} 适合轮廓最小内侧半径 {2}、且刀路不碰轮廓的最大平底立铣刀（{0}）；其刃长（{3}）短于 T：分层切削</translation>
        </message>
        <message>
            <source>largest flat end mill ({}) whose radius {} fits the contour's smallest inside radius {} and whose passes keep off the contour</source>
            <translation>半径 {1} 适合轮廓最小内侧半径 {2}、且刀路不碰轮廓的最大平底立铣刀（{0}）</translation>
        </message>
        <message>
            <source>largest flat end mill ({}) and whose passes keep off the contour; its flutes ({}) are shorter than T: it cuts in layers</source>
            <translation>刀路不碰轮廓的最大平底立铣刀（{0}）；其刃长（{1}）短于 T：分层切削</translation>
        </message>
        <message>
            <source>largest flat end mill ({}) and whose passes keep off the contour</source>
            <translation>刀路不碰轮廓的最大平底立铣刀（{}）</translation>
        </message>
        <message>
            <source>the arc of {} at ({}, {}) curves round the tool's side with radius {}: the smallest end mill, {}, is {} too large for it (an arc of radius {} or more would let it fit)</source>
            <translation>{0} 在 ({1}, {2}) 处的圆弧以半径 {3} 弯向刀具一侧：最小的立铣刀 {4} 比它大 {5}（圆弧半径为 {6} 或以上即可容纳）</translation>
        </message>
        <message>
            <source>name the contour the side milling follows (a CONTOUR of the job's figure elements, open or closed)</source>
            <translation>请指定侧铣所沿的轮廓（作业图形元素中的 CONTOUR，开放或闭合均可）</translation>
        </message>
        <message>
            <source>{} {} is not a code of side milling; use {}</source>
            <translation>{} {} 不是侧铣的代码；请使用 {}</translation>
        </message>
        <message>
            <source>the width W is {}; roughing leaves α2 = {} on the wall, so W must be larger than that</source>
            <translation>宽度 W 为 {}；粗加工在壁上留 α2 = {}，因此 W 必须大于该值</translation>
        </message>
        <message>
            <source>{}: {}</source>
            <translation>{}：{}</translation>
        </message>
        <message>
            <source>{} does not fit where {} narrows near ({}, {}): the tool would cut into the contour there; pin a smaller end mill or widen the channel</source>
            <translation>{0} 在 {1} 变窄的（{2}, {3}）附近放不下：刀具会切入轮廓；请指定更小的立铣刀或加宽通道</translation>
        </message>
        <message>
            <source>curve 1</source>
            <translation>曲线 1</translation>
        </message>
        <message>
            <source>curve 2</source>
            <translation>曲线 2</translation>
        </message>
        <message>
            <source>the figure has no contour {}; its open contours: {}</source>
            <translation>图形中没有轮廓 {0}；其开放轮廓: {1}</translation>
        </message>
        <message>
            <source>contour {} is closed; a projection runs from one end to the other</source>
            <translation>轮廓 {0} 是封闭的；投影应从一端到另一端</translation>
        </message>
        <message>
            <source>{} has one point; give two or more [x, y, z]</source>
            <translation>{} 只有一个点；请给出两个或更多点 [x, y, z]</translation>
        </message>
        <message>
            <source>{} has neither points [x, y, z] nor two projections (XY, YZ or ZX)</source>
            <translation>{} 既没有点 [x, y, z]，也没有两个投影（XY、YZ 或 ZX）</translation>
        </message>
        <message>
            <source>{}: projection {} is in plane "{}"; give XY, YZ or ZX</source>
            <translation>{}：投影 {} 位于平面 "{}"；请给出 XY、YZ 或 ZX</translation>
        </message>
        <message>
            <source>projection {}: {}</source>
            <translation>投影 {}：{}</translation>
        </message>
        <message>
            <source>{} "{}" does not read: give points "x, y, z; x, y, z" or two projections "XY: a, b; a, b / ZX: a, b; a, b"</source>
            <translation>无法读取{} "{}"：请给出点 "x, y, z; x, y, z" 或两个投影 "XY: a, b; a, b / ZX: a, b; a, b"</translation>
        </message>
        <message>
            <source>the surface needs at least 2 paths of 2 points or more</source>
            <translation>曲面至少需要 2 条路径，每条 2 个点或更多</translation>
        </message>
        <message>
            <source>path {} has {} points; every path has as many as the first ({})</source>
            <translation>路径 {} 有 {} 个点；每条路径的点数都应与第一条相同（{}）</translation>
        </message>
        <message>
            <source>N {} must be 1 or more: the roughing surface needs pieces</source>
            <translation>N {} 必须为 1 或更大：粗加工曲面需要分段</translation>
        </message>
        <message>
            <source>give M (the finishing surface's pieces) or the step along the curves that implies it</source>
            <translation>请给出 M（精加工曲面的分段数）或决定它的沿曲线步距</translation>
        </message>
        <message>
            <source>N {} is not less than M {}: the finishing surface must be divided more finely than the roughing surface (N &lt; M)</source>
            <translation>N {} 不小于 M {}：精加工曲面的分段必须比粗加工曲面更细（N &lt; M）</translation>
        </message>
        <message>
            <source>the surface rises to Z {} above the stock top (Z 0); the surface is cut into the stock from above</source>
            <translation>曲面升至 Z {}，高于毛坯顶面（Z 0）；曲面是从上方切入毛坯加工的</translation>
        </message>
        <message>
            <source>the surface goes down to Z {}, through the stock's bottom (height {})</source>
            <translation>曲面下降至 Z {}，穿过了毛坯底面（高度 {}）</translation>
        </message>
        <message>
            <source>the scallop height {} must be greater than 0</source>
            <translation>残留高度 {} 必须大于 0</translation>
        </message>
        <message>
            <source>the allowance {} must be 0 or more</source>
            <translation>余量 {} 必须为 0 或更大</translation>
        </message>
        <message>
            <source>the boundary "{}" does not read: give paths of points "x, y, z; x, y, z" separated by "/"</source>
            <translation>无法读取边界 "{}"：请给出由点 "x, y, z; x, y, z" 组成、以 "/" 分隔的路径</translation>
        </message>
        <message>
            <source>the boundary makes no surface: give two or more paths with the same number of points</source>
            <translation>边界构不成曲面：请给出两条或更多点数相同的路径</translation>
        </message>
        <message>
            <source>the boundary surface never meets the surface: no path would stop at it; move it onto the surface or leave it out</source>
            <translation>边界曲面与加工曲面没有交点：没有路径会在此停止；请把它移到曲面上，或去掉边界</translation>
        </message>
        <message>
            <source>{} is pinned for "surface" but is not a ball end mill</source>
            <translation>{} 被指定用于 "surface"，但不是球头立铣刀</translation>
        </message>
        <message>
            <source>{} is pinned for "surface" but its radius {} is not less than the surface's smallest concave radius {} ({}); {} would fit</source>
            <translation>{} 被指定用于 "surface"，但其半径 {} 不小于曲面的最小凹半径 {}（{}）；{} 可以放入</translation>
        </message>
        <message>
            <source>{} is pinned for "surface" but its radius {} is not less than the surface's smallest concave radius {} ({}), and the library has no smaller ball end mill</source>
            <translation>{} 被指定用于 "surface"，但其半径 {} 不小于曲面的最小凹半径 {}（{}），且刀具库中没有更小的球头立铣刀</translation>
        </message>
        <message>
            <source>the tool library has no ball end mill; add one</source>
            <translation>刀具库中没有球头立铣刀；请添加一把</translation>
        </message>
        <message>
            <source>the tool library has no ball end mill with a radius less than the surface's smallest concave radius {} ({}); add a smaller one</source>
            <translation>刀具库中没有半径小于曲面最小凹半径 {}（{}）的球头立铣刀；请添加更小的</translation>
        </message>
        <message>
            <source>largest ball end mill (Ø{:g} mm); the surface has no concave bend</source>
            <translation>最大的球头立铣刀（Ø{} mm）；曲面没有凹弯</translation>
        </message>
        <message>
            <source>largest ball end mill (Ø{:g} mm) under the smallest concave radius {} ({})</source>
            <translation>小于最小凹半径 {1}（{2}）的最大球头立铣刀（Ø{0} mm）</translation>
        </message>
        <message>
            <source>a TURN unit</source>
            <translation>TURN 单元</translation>
        </message>
        <message>
            <source>the start point</source>
            <translation>起点</translation>
        </message>
        <message>
            <source>an array of profile rows</source>
            <translation>轮廓行数组</translation>
        </message>
        <message>
            <source>a profile row</source>
            <translation>轮廓行</translation>
        </message>
        <message>
            <source>a thread</source>
            <translation>螺纹</translation>
        </message>
        <message>
            <source>an array of grinding-allowance rows</source>
            <translation>磨削余量行数组</translation>
        </message>
        <message>
            <source>a grinding-allowance row</source>
            <translation>磨削余量行</translation>
        </message>
        <message>
            <source>an array of step names</source>
            <translation>工序名数组</translation>
        </message>
        <message>
            <source>a step name</source>
            <translation>工序名</translation>
        </message>
        <message>
            <source>the {} has {} rows; a turned profile has at most {} (split the part into several units)</source>
            <translation>{}有 {} 行；车削轮廓最多 {} 行（请将零件拆分为多个单元）</translation>
        </message>
        <message>
            <source>"{}" is not a turning step; steps are {}</source>
            <translation>“{}”不是车削工序；工序为 {}</translation>
        </message>
        <message>
            <source>{} is on an inner profile: internal threads are not cut yet (only external ones)</source>
            <translation>{} 位于内轮廓上：尚不能车内螺纹（仅外螺纹）</translation>
        </message>
        <message>
            <source>{} is an arc: a thread is cut on a straight row along the axis</source>
            <translation>{} 是圆弧：螺纹只在沿轴线的直线行上车削</translation>
        </message>
        <message>
            <source>{} is not a cylinder cut toward the chuck (a taper or a face): a thread is cut on a straight row along the axis, from the front back</source>
            <translation>{} 不是朝卡盘方向车削的圆柱（而是锥面或端面）：螺纹在沿轴线的直线行上由前向后车削</translation>
        </message>
        <message>
            <source>{} has a grinding allowance: a thread is not ground</source>
            <translation>{} 有磨削余量：螺纹不进行磨削</translation>
        </message>
        <message>
            <source>a pitch of {} is out of range: {} to {}</source>
            <translation>螺距 {} 超出范围：{} 到 {}</translation>
        </message>
        <message>
            <source>a thread {} deep does not fit Ø{} with pitch {}: at most {} (the sharp V's height, and a core of half the diameter)</source>
            <translation>深 {0} 的螺纹在螺距 {2} 下放不进 Ø{1}：最多 {3}（尖 V 形高度，且芯径为直径一半）</translation>
        </message>
        <message>
            <source>no external threading insert of the tool library cuts a pitch of {}</source>
            <translation>刀具库中没有能车削螺距 {} 的外螺纹刀片</translation>
        </message>
        <message>
            <source>the profile reaches Ø{}, more than the bar's Ø{}</source>
            <translation>轮廓达到 Ø{}，大于棒料的 Ø{}</translation>
        </message>
        <message>
            <source>the profile with its grinding allowances reaches Ø{}, more than the bar's Ø{}</source>
            <translation>含磨削余量的轮廓达到 Ø{}，大于棒料的 Ø{}</translation>
        </message>
        <message>
            <source>the profile reaches Z{}, beyond the bar's face stock (Z{})</source>
            <translation>轮廓达到 Z{}，超出棒料端面余量（Z{}）</translation>
        </message>
        <message>
            <source>the profile reaches Z{}, beyond the bar's end (Z{})</source>
            <translation>轮廓达到 Z{}，超出棒料末端（Z{}）</translation>
        </message>
        <message>
            <source>pinned</source>
            <translation>由操作员指定</translation>
        </message>
        <message>
            <source>the bar has face stock but the tool library has no outside turning insert to face it</source>
            <translation>棒料有端面余量，但刀具库中没有可车端面的外圆车刀片</translation>
        </message>
        <message>
            <source>the outside roughing insert faces the bar (largest nose radius)</source>
            <translation>用外圆粗车刀片车端面（刀尖半径最大）</translation>
        </message>
        <message>
            <source>the bore is too narrow for the boring bar (it enters {}; the bore less its allowance leaves {}) and no drill of the library makes it to size</source>
            <translation>孔对镗杆太窄（镗杆需 {}；孔径减去余量为 {}），且刀具库中没有可加工到此尺寸的钻头</translation>
        </message>
        <message>
            <source>the bore needs a drilled hole of {} to {} (the boring bar enters {}), and the tool library has no drill in that range</source>
            <translation>镗孔需要 {} 到 {} 的预钻孔（镗杆需 {}），但刀具库中没有此范围的钻头</translation>
        </message>
        <message>
            <source>largest drill within the bore less its allowance ({}), not smaller than the boring bar's bore {}</source>
            <translation>在孔径减去镗孔余量（{}）以内、且不小于镗杆所需孔径 {} 的最大钻头</translation>
        </message>
        <message>
            <source>smallest centre drill</source>
            <translation>最小的中心钻</translation>
        </message>
        <message>
            <source>the tool library has no inside (boring) turning insert</source>
            <translation>刀具库中没有内孔（镗孔）车刀片</translation>
        </message>
        <message>
            <source>the tool library has no outside turning insert</source>
            <translation>刀具库中没有外圆车刀片</translation>
        </message>
        <message>
            <source>reaches every element; smallest nose radius of those that do</source>
            <translation>可到达所有元素；其中刀尖半径最小</translation>
        </message>
        <message>
            <source>reaches all but {} element(s); smallest nose radius of those that reach most</source>
            <translation>有 {} 个元素无法到达；到达最多者中刀尖半径最小</translation>
        </message>
        <message>
            <source>widest grooving blade not wider than the groove ({})</source>
            <translation>不宽于槽宽（{}）的最宽切槽刀</translation>
        </message>
        <message>
            <source>narrowest grooving blade; it reaches {} from the air beside it</source>
            <translation>最窄的切槽刀；从旁边的空处到达 {}</translation>
        </message>
        <message>
            <source>narrowest parting blade for {}</source>
            <translation>适用于 {} 的最窄切断刀</translation>
        </message>
        <message>
            <source>{} is not an inside turning insert</source>
            <translation>{} 不是内孔车刀片</translation>
        </message>
        <message>
            <source>{} is not an outside turning insert</source>
            <translation>{} 不是外圆车刀片</translation>
        </message>
        <message>
            <source>largest nose radius for its side (the strongest edge)</source>
            <translation>该侧刀尖半径最大（刃口最强）</translation>
        </message>
        <message>
            <source>external threading insert for pitch {}</source>
            <translation>螺距 {} 的外螺纹车刀片</translation>
        </message>
        <message>
            <source>plane</source>
            <translation>平面</translation>
        </message>
        <message>
            <source>cylinder</source>
            <translation>圆柱面</translation>
        </message>
        <message>
            <source>cone</source>
            <translation>圆锥面</translation>
        </message>
        <message>
            <source>sphere</source>
            <translation>球面</translation>
        </message>
        <message>
            <source>torus</source>
            <translation>圆环面</translation>
        </message>
        <message>
            <source>surface of revolution</source>
            <translation>回转面</translation>
        </message>
        <message>
            <source>Bézier surface</source>
            <translation>贝塞尔曲面</translation>
        </message>
        <message>
            <source>B-spline surface</source>
            <translation>B 样条曲面</translation>
        </message>
        <message>
            <source>extruded surface</source>
            <translation>拉伸面</translation>
        </message>
        <message>
            <source>offset surface</source>
            <translation>偏置面</translation>
        </message>
        <message>
            <source>free-form surface</source>
            <translation>自由曲面</translation>
        </message>
        <message>
            <source>cannot open it (no such file)</source>
            <translation>无法打开（文件不存在）</translation>
        </message>
        <message>
            <source>not a STEP file, or a broken one</source>
            <translation>不是 STEP 文件，或文件已损坏</translation>
        </message>
        <message>
            <source>the file holds no solid: a turned part is imported from its solid model</source>
            <translation>文件中没有实体：车削零件从其实体模型导入</translation>
        </message>
        <message>
            <source>the file holds {} solids; import one turned part at a time</source>
            <translation>文件中有 {} 个实体；请一次导入一个车削零件</translation>
        </message>
        <message>
            <source>not a body of revolution: face {} is a {}, not turned about an axis</source>
            <translation>不是回转体：面 {} 是{}，不是绕轴回转的面</translation>
        </message>
        <message>
            <source>not a body of revolution: no face of it is turned about an axis (cylinder, cone, torus, sphere)</source>
            <translation>不是回转体：没有绕轴回转的面（圆柱面、圆锥面、圆环面、球面）</translation>
        </message>
        <message>
            <source>not a body of revolution: face {} (a {}) is not turned about the axis of face {} (a {})</source>
            <translation>不是回转体：面 {0}（{1}）不绕面 {2}（{3}）的轴回转</translation>
        </message>
        <message>
            <source>not a body of revolution: face {} (a {}) is not centred on the axis of face {} (a {})</source>
            <translation>不是回转体：面 {0}（{1}）的中心不在面 {2}（{3}）的轴上</translation>
        </message>
        <message>
            <source>not a body of revolution: face {} (a {}) is not square to the axis of face {} (a {})</source>
            <translation>不是回转体：面 {0}（{1}）与面 {2}（{3}）的轴不垂直</translation>
        </message>
        <message>
            <source>OpenCASCADE could not cut the part with the half-plane</source>
            <translation>OpenCASCADE 无法用半平面剖切零件</translation>
        </message>
        <message>
            <source>the half-section has an edge that is neither a line nor an arc</source>
            <translation>半剖面中有既非直线也非圆弧的边</translation>
        </message>
        <message>
            <source>the half-plane through the axis does not cut the part</source>
            <translation>过轴的半平面没有剖切到零件</translation>
        </message>
        <message>
            <source>the half-section's outline does not close</source>
            <translation>半剖面的轮廓不封闭</translation>
        </message>
        <message>
            <source>the half-section falls into several pieces (a closed cavity inside the part?)</source>
            <translation>半剖面分成了多块（零件内部有封闭空腔？）</translation>
        </message>
        <message>
            <source>{}: OpenCASCADE failed reading it: {}</source>
            <translation>{}：OpenCASCADE 读取失败：{}</translation>
        </message>
        <message>
            <source>paths {} and {}, points {} to {} (X {:.3f} Y {:.3f} Z {:.3f}): the surface turns under itself; the verifying simulation is a height field and cannot see undercuts</source>
            <translation>路径 {} 和 {}，点 {} 至 {}（X {} Y {} Z {}）：曲面折回到自身下方；验证仿真是高度场，看不到倒扣</translation>
        </message>
        <message>
            <source>path {}, point {} (X {:.3f} Y {:.3f} Z {:.3f})</source>
            <translation>路径 {} 的点 {}（X {} Y {} Z {}）</translation>
        </message>
        <message>
            <source>projection {} ({}): {}</source>
            <translation>投影 {}（{}）：{}</translation>
        </message>
        <message>
            <source>it needs at least two points, it has {}</source>
            <translation>至少需要两个点，现在只有 {} 个</translation>
        </message>
        <message>
            <source>projection {} ({}), point {} ({} {:.4f}): {} must rise or fall all along the curve, it {} after point {}</source>
            <translation>投影 {0}（{1}），点 {2}（{3} {4}）：{5} 必须沿整条曲线单调增加或减少，但在点 {7} 之后{6}</translation>
        </message>
        <message>
            <source>stands still</source>
            <translation>保持不变</translation>
        </message>
        <message>
            <source>turns back</source>
            <translation>折返</translation>
        </message>
        <message>
            <source>the division step must be above 0, not {}</source>
            <translation>分割步距必须大于 0，而不是 {}</translation>
        </message>
        <message>
            <source>projection 2 lies in the same plane ({}) as projection 1: a space curve needs two planes</source>
            <translation>投影 2 与投影 1 位于同一平面（{}）：空间曲线需要两个平面</translation>
        </message>
        <message>
            <source>projection 2 ({}): its {} range {:.4f} to {:.4f} does not overlap projection 1's ({}) {:.4f} to {:.4f}</source>
            <translation>投影 2（{}）：其 {} 范围 {} 至 {} 与投影 1（{}）的 {} 至 {} 不重叠</translation>
        </message>
        <message>
            <source>projections {} and {}: OpenCASCADE refused them ({})</source>
            <translation>投影 {} 和 {}：OpenCASCADE 拒绝了它们（{}）</translation>
        </message>
        <message>
            <source>the step-over must be above 0, not {}</source>
            <translation>沿曲线的步距必须大于 0，而不是 {}</translation>
        </message>
        <message>
            <source>it needs at least two points</source>
            <translation>至少需要两个点</translation>
        </message>
        <message>
            <source>OpenCASCADE could not measure it ({})</source>
            <translation>OpenCASCADE 无法测量其长度（{}）</translation>
        </message>
        <message>
            <source>curve 1: {}</source>
            <translation>曲线 1：{}</translation>
        </message>
        <message>
            <source>curve 2: {}</source>
            <translation>曲线 2：{}</translation>
        </message>
        <message>
            <source>the curve: {}</source>
            <translation>曲线：{}</translation>
        </message>
        <message>
            <source>it must be divided into at least 1 piece, not {}</source>
            <translation>必须至少分成 1 段，而不是 {}</translation>
        </message>
        <message>
            <source>points {} and {} are the same point</source>
            <translation>点 {} 与点 {} 是同一点</translation>
        </message>
        <message>
            <source>OpenCASCADE could not divide it into {} pieces</source>
            <translation>OpenCASCADE 无法将其分成 {} 段</translation>
        </message>
        <message>
            <source>OpenCASCADE refused it ({})</source>
            <translation>OpenCASCADE 拒绝了它（{}）</translation>
        </message>
        <message>
            <source>the spacing {} must be above 0</source>
            <translation>间距 {} 必须大于 0</translation>
        </message>
        <message>
            <source>{}: a face lies under another at {} (Z {:.3f} under Z {:.3f}); a surface machined from above has none (the verifying simulation is a height field)</source>
            <translation>{}：在 {} 处有一个面位于另一个面之下（Z {} 在 Z {} 之下）；从上方加工的曲面不能有这种情况（验证仿真是高度场）</translation>
        </message>
        <message>
            <source>{}: {} × {} points at a spacing of {} mm; a surface holds at most {} (give a larger spacing)</source>
            <translation>{0}：以 {3} mm 的间距为 {1} × {2} 个点；曲面最多容纳 {4} 个点（请增大间距）</translation>
        </message>
        <message>
            <source>{}: no face lies under {}: the faces seen from above leave a hole or are not a rectangle; the surface must cover its X-Y rectangle</source>
            <translation>{}：{} 下方没有面：从上方看这些面留有孔或不成矩形；曲面必须覆盖其 X-Y 矩形</translation>
        </message>
        <message>
            <source>N: the roughing surface needs at least 1 piece, not {}</source>
            <translation>N：粗加工曲面至少需要 1 段，而不是 {}</translation>
        </message>
        <message>
            <source>M: the finishing surface's pieces (M = {}) must be more than the roughing surface's (N = {})</source>
            <translation>M：精加工曲面的分段数（M = {}）必须多于粗加工曲面的分段数（N = {}）</translation>
        </message>
        <message>
            <source>the ruled surface needs two curves of the same number of points, at least two</source>
            <translation>直纹面需要两条点数相同（至少两个点）的曲线</translation>
        </message>
        <message>
            <source>the ruled surface is not a plane within {} mm</source>
            <translation>直纹面在 {} mm 以内不是平面</translation>
        </message>
        <message>
            <source>the ruled surface: OpenCASCADE refused it ({})</source>
            <translation>直纹面：OpenCASCADE 拒绝了它（{}）</translation>
        </message>
        <message>
            <source>the surface's paths: at least 2 paths of 2 points are needed, there are {}</source>
            <translation>曲面的路径：至少需要 2 条含 2 个点的路径，现在有 {} 条</translation>
        </message>
        <message>
            <source>the surface's paths: path {} has {} points, path 1 has {}</source>
            <translation>曲面的路径：路径 {} 有 {} 个点，而路径 1 有 {} 个</translation>
        </message>
        <message>
            <source>the surface's paths: OpenCASCADE could not interpolate them</source>
            <translation>曲面的路径：OpenCASCADE 无法对其插值</translation>
        </message>
        <message>
            <source>{}: OpenCASCADE could not put the surface into STEP</source>
            <translation>{}：OpenCASCADE 无法将曲面转换为 STEP</translation>
        </message>
        <message>
            <source>{}: the STEP file could not be written</source>
            <translation>{}：无法写入 STEP 文件</translation>
        </message>
        <message>
            <source>{}: OpenCASCADE refused the surface ({})</source>
            <translation>{}：OpenCASCADE 拒绝了该曲面（{}）</translation>
        </message>
        <message>
            <source>no temporary folder for the STEP file: {}</source>
            <translation>没有可放 STEP 文件的临时文件夹：{}</translation>
        </message>
        <message>
            <source>{}: the STEP file written could not be read back</source>
            <translation>{}：无法读回已写入的 STEP 文件</translation>
        </message>
        <message>
            <source>{}: no such file</source>
            <translation>{}：文件不存在</translation>
        </message>
        <message>
            <source>{}: not a STEP file OpenCASCADE can read</source>
            <translation>{}：不是 OpenCASCADE 能读取的 STEP 文件</translation>
        </message>
        <message>
            <source>{}: the STEP file holds no shape</source>
            <translation>{}：STEP 文件中没有形状</translation>
        </message>
        <message>
            <source>{}: the STEP file holds no face</source>
            <translation>{}：STEP 文件中没有面</translation>
        </message>
        <message>
            <source>{}: its {} faces gave no triangles</source>
            <translation>{}：其 {} 个面未生成任何三角形</translation>
        </message>
        <message>
            <source>{}: OpenCASCADE refused it ({})</source>
            <translation>{}：OpenCASCADE 拒绝了它（{}）</translation>
        </message>
        <message>
            <source>{} to {}</source>
            <translation>{} 至 {}</translation>
        </message>
        <message>
            <source>{} and {}</source>
            <translation>{} 和 {}</translation>
        </message>
        <message>
            <source>work offset '{}' cannot be posted for {}: {}; {} offers {}</source>
            <translation>工件坐标系 '{0}' 无法为 {1} 输出：{2}；{3} 提供 {4}</translation>
        </message>
        <message>
            <source>{} has no {}</source>
            <translation>{} 没有 {}</translation>
        </message>
        <message>
            <source>G154 P (Haas' extended work offsets)</source>
            <translation>G154 P（Haas 的扩展工件坐标系）</translation>
        </message>
        <message>
            <source>G54.1 P (FANUC's extended work offsets)</source>
            <translation>G54.1 P（FANUC 的扩展工件坐标系）</translation>
        </message>
        <message>
            <source>there is no {}</source>
            <translation>没有 {}</translation>
        </message>
        <message>
            <source>not a work offset</source>
            <translation>不是工件坐标系</translation>
        </message>
        <message>
            <source>the SINUMERIK manual pages at hand do not say which probe edge MEAS=1 and MEAS=-1 take, how $AC_MEA reports a touch not made, nor that STOPRE must come before $AA_MW is read; see docs/probing.md</source>
            <translation>现有的 SINUMERIK 手册未说明 MEAS=1 和 MEAS=-1 取哪个测头沿、未触碰时 $AC_MEA 如何报告，也未说明读取 $AA_MW 前必须先 STOPRE；参见 docs/probing.md</translation>
        </message>
        <message>
            <source>the TNC manual pages at hand do not say what TCH PROBE 0 does when nothing is touched, and the one way found to write a preset from a program, FN 17: SYSWRITE, is locked behind the machine maker's code number; see docs/probing.md</source>
            <translation>现有的 TNC 手册未说明未触碰任何物体时 TCH PROBE 0 如何动作，而从程序写入预设的唯一方法 FN 17: SYSWRITE 受机床厂商密码保护；参见 docs/probing.md</translation>
        </message>
        <message>
            <source>the {} dialect writes no lathe tapes (Klartext is a milling control's language); {} can</source>
            <translation>数控系统 {} 不输出车床程序（Klartext 是铣床控制系统的语言）；可输出的有 {}</translation>
        </message>
        <message>
            <source>the {} dialect writes no probing unit's programs; {} can ({})</source>
            <translation>数控系统 {} 不输出测量单元的程序；可输出的有 {}（{}）</translation>
        </message>
        <message>
            <source>machine: {} is a two-path lathe and the job has no roughing step to balance between its paths</source>
            <translation>machine: {} 是双通道车床，但作业中没有可在两个通道之间平衡的粗加工工序</translation>
        </message>
        <message>
            <source>ER32 collet chuck</source>
            <translation>ER32 弹簧夹头</translation>
        </message>
        <message>
            <source>Tapping chuck ER32</source>
            <translation>攻丝夹头 ER32</translation>
        </message>
        <message>
            <source>HSK63 shrink-fit</source>
            <translation>HSK63 热缩刀柄</translation>
        </message>
        <message>
            <source>HSK63 boring head</source>
            <translation>HSK63 镗头</translation>
        </message>
        <message>
            <source>GHDR 26-3 parting</source>
            <translation>GHDR 26-3 切断</translation>
        </message>
        <message>
            <source>ER16 collet chuck</source>
            <translation>ER16 弹簧夹头</translation>
        </message>
        <message>
            <source>Weldon side lock</source>
            <translation>侧固式刀柄(Weldon)</translation>
        </message>
        <message>
            <source>HSK63 shell mill arbor</source>
            <translation>HSK63 套式铣刀刀杆</translation>
        </message>
        <message>
            <source>HSK63 probe body</source>
            <translation>HSK63 测头本体</translation>
        </message>
        <message>
            <source>reading the history of tool T{}</source>
            <translation>读取刀具 T{} 的历史</translation>
        </message>
        <message>
            <source>{}: job '{}': a name, and text without NUL characters, are needed</source>
            <translation>{}：作业 '{}'：需要名称以及不含 NUL 字符的文本</translation>
        </message>
        <message>
            <source>job '{}' is open at station {} (by {} since {}); it was not saved</source>
            <translation>作业 '{}' 正在工位 {} 打开（{}，自 {} 起）；未保存</translation>
        </message>
        <message>
            <source>{}: saving job '{}' failed ({})</source>
            <translation>{}：保存作业 '{}' 失败（{}）</translation>
        </message>
        <message>
            <source>{}: opening job '{}' failed ({})</source>
            <translation>{}：打开作业 '{}' 失败（{}）</translation>
        </message>
        <message>
            <source>{} has no version {} of job '{}'</source>
            <translation>{} 没有作业 '{}' 的第 {} 版</translation>
        </message>
        <message>
            <source>{} has no job '{}'</source>
            <translation>{} 没有作业 '{}'</translation>
        </message>
        <message>
            <source>{}: reading the history of job '{}' failed ({})</source>
            <translation>{}：读取作业 '{}' 的历史失败（{}）</translation>
        </message>
        <message>
            <source>{}: listing the jobs failed ({})</source>
            <translation>{}：列出作业失败（{}）</translation>
        </message>
        <message>
            <source>{}: locking job '{}' failed ({})</source>
            <translation>{}：锁定作业 '{}' 失败（{}）</translation>
        </message>
        <message>
            <source>job '{}' is open at station {} (by {} since {})</source>
            <translation>作业 '{}' 正在工位 {} 打开（{}，自 {} 起）</translation>
        </message>
        <message>
            <source>{}: unlocking job '{}' failed ({})</source>
            <translation>{}：解锁作业 '{}' 失败（{}）</translation>
        </message>
        <message>
            <source>job '{}' is open at station {} (by {} since {}) and that station is connected to the server now; its lock was not released</source>
            <translation>作业 '{}' 正在工位 {} 打开（{}，自 {} 起），该工位当前已连接服务器；其锁未被释放</translation>
        </message>
        <message>
            <source>{}: the local copy {} could not be written</source>
            <translation>{}：无法写入本地副本 {}</translation>
        </message>
        <message>
            <source>{}: the local copy {} could not be written ({})</source>
            <translation>{}：无法写入本地副本 {}（{}）</translation>
        </message>
        <message>
            <source>{} cannot be reached ({}) and this station has no copy of its tools yet</source>
            <translation>无法连接 {}（{}），且本工位尚无其刀具副本</translation>
        </message>
        <message>
            <source>{} cannot be reached ({}): the tools are as of {} and cannot be edited until it is back</source>
            <translation>无法连接 {}（{}）：刀具为 {} 时的状态，恢复连接前无法编辑</translation>
        </message>
        <message>
            <source>tools as of {} (read only: {} cannot be reached)</source>
            <translation>{} 时的刀具（只读：无法连接 {}）</translation>
        </message>
        <message>
            <source>tools: {}</source>
            <translation>刀具：{}</translation>
        </message>
        <message>
            <source>{}: tool T{} ({}): {}</source>
            <translation>{}：刀具 T{}（{}）：{}</translation>
        </message>
        <message>
            <source>{}: tool T{} ({}) holds a NUL character, which the server cannot store</source>
            <translation>{}：刀具 T{}（{}）含有 NUL 字符，服务器无法保存</translation>
        </message>
        <message>
            <source>saving tool T{}</source>
            <translation>保存刀具 T{}</translation>
        </message>
        <message>
            <source>reading tool T{}</source>
            <translation>读取刀具 T{}</translation>
        </message>
        <message>
            <source>{} has no tool T{}</source>
            <translation>{} 中没有刀具 T{}</translation>
        </message>
        <message>
            <source>removing tool T{}</source>
            <translation>删除刀具 T{}</translation>
        </message>
        <message>
            <source>adding usage to tool T{}</source>
            <translation>为刀具 T{} 累加使用时间</translation>
        </message>
        <message>
            <source>{} cannot be read ({})</source>
            <translation>无法读取 {}（{}）</translation>
        </message>
        <message>
            <source>tool T{} ({}) holds a NUL character</source>
            <translation>刀具 T{}（{}）含有 NUL 字符</translation>
        </message>
        <message>
            <source>importing {}</source>
            <translation>导入 {}</translation>
        </message>
        <message>
            <source>{}: {} failed ({})</source>
            <translation>{}：{} 失败（{}）</translation>
        </message>
        <message>
            <source>{} was set up by a newer Taiwa (schema version {}); this program knows version {}</source>
            <translation>{} 由较新的 Taiwa 建立（架构版本 {}）；本程序支持到版本 {}</translation>
        </message>
        <message>
            <source>{}: the schema could not be brought from version {} to {} ({}); a station's role may only read and write, the owner upgrades it (docs/shop-server.md)</source>
            <translation>{}：无法将架构从版本 {} 升级到 {}（{}）；工位的角色只能读写，由所有者升级（docs/shop-server.md）</translation>
        </message>
        <message>
            <source>TAIWA_TOOL_DB: '{}' is not a server address ({})</source>
            <translation>TAIWA_TOOL_DB：'{}' 不是服务器地址（{}）</translation>
        </message>
        <message>
            <source>TAIWA_TOOL_DB: the address of {} holds a password; put it in ~/.pgpass or the service file instead (docs/shop-server.md)</source>
            <translation>TAIWA_TOOL_DB：{} 的地址中含有密码；请改写在 ~/.pgpass 或服务文件中（docs/shop-server.md）</translation>
        </message>
        <message>
            <source>the name says {:g} mm, the diameter is {:g} mm</source>
            <translation>名称写的是 {:g} mm，直径却是 {:g} mm</translation>
        </message>
        <message>
            <source>T number {} must be 1 to {}</source>
            <translation>T 号 {} 必须为 1 到 {}</translation>
        </message>
        <message>
            <source>diameter {:g} mm is more than 500 mm</source>
            <translation>直径 {} mm 超过 500 mm</translation>
        </message>
        <message>
            <source>corner radius {:g} mm must not be negative</source>
            <translation>圆角半径 {} mm 不能为负</translation>
        </message>
        <message>
            <source>corner radius {:g} mm is more than half the diameter ({:g} mm)</source>
            <translation>圆角半径 {} mm 大于直径的一半（{} mm）</translation>
        </message>
        <message>
            <source>taper {:g}° per side must be 0 to less than 45°</source>
            <translation>单边锥度 {}° 必须为 0 到小于 45°</translation>
        </message>
        <message>
            <source>flute length {:g} mm must not be negative</source>
            <translation>刃长 {} mm 不能为负</translation>
        </message>
        <message>
            <source>holder Ø {:g} mm must not be negative</source>
            <translation>刀柄直径 Ø {} mm 不能为负</translation>
        </message>
        <message>
            <source>holder Ø {:g} mm is narrower than the tool (Ø {:g} mm)</source>
            <translation>刀柄直径 Ø {} mm 小于刀具（Ø {} mm）</translation>
        </message>
        <message>
            <source>holder length {:g} mm must not be negative</source>
            <translation>刀柄长度 {} mm 不能为负</translation>
        </message>
        <message>
            <source>stick-out {:g} mm must not be negative</source>
            <translation>悬伸长度 {} mm 不能为负</translation>
        </message>
        <message>
            <source>stick-out {:g} mm is shorter than the flutes ({:g} mm)</source>
            <translation>悬伸长度 {} mm 短于刃长（{} mm）</translation>
        </message>
        <message>
            <source>a tap's pitch {:g} mm must be greater than zero, at most 10 mm (one pitch)</source>
            <translation>丝锥螺距 {} mm 必须大于零且不超过 10 mm（一个螺距）</translation>
        </message>
        <message>
            <source>life {:g} min must not be negative</source>
            <translation>寿命 {} 分钟不能为负</translation>
        </message>
        <message>
            <source>used {:g} min must not be negative</source>
            <translation>已用时间 {} 分钟不能为负</translation>
        </message>
        <message>
            <source>it is a {}, the step needs a {}</source>
            <translation>它是{}，该工序需要{}</translation>
        </message>
        <message>
            <source>it has no cutting data for {}</source>
            <translation>没有 {} 的切削参数</translation>
        </message>
        <message>
            <source>its taper is {:g} deg per side, the wall's is {:g}</source>
            <translation>其锥度为单边 {} 度，壁的锥度为 {} 度</translation>
        </message>
        <message>
            <source>its radius {:g} mm is larger than the corner radius {:g} mm</source>
            <translation>其半径 {} mm 大于圆角半径 {} mm</translation>
        </message>
        <message>
            <source>it does not cut at its centre, so it cannot ramp in without a pilot hole</source>
            <translation>它不能中心切削，因此没有预钻孔就无法斜坡下刀</translation>
        </message>
        <message>
            <source>its diameter {:g} mm is too large for the pocket</source>
            <translation>其直径 {} mm 对型腔过大</translation>
        </message>
        <message>
            <source>its diameter {:g} mm is smaller than the {:g} mm needed</source>
            <translation>其直径 {} mm 小于所需的 {} mm</translation>
        </message>
        <message>
            <source>its flutes ({:g} mm) are shorter than the depth {:g} mm</source>
            <translation>其刃长（{} mm）短于深度 {} mm</translation>
        </message>
        <message>
            <source>its stick-out ({:g} mm) is shorter than the depth {:g} mm</source>
            <translation>其悬伸长度（{} mm）短于深度 {} mm</translation>
        </message>
        <message>
            <source>no taper end mill of {:g} deg per side in the tool library for the {}</source>
            <translation>刀具库中没有用于{1}的单边 {0} 度锥度立铣刀</translation>
        </message>
        <message>
            <source>no {} in the tool library for the {}</source>
            <translation>刀具库中没有用于{1}的{0}</translation>
        </message>
        <message>
            <source>no {} in the tool library fits the {}: T{} ({}) is the nearest, but {}</source>
            <translation>刀具库中没有适合{1}的{0}：最接近的是 T{2}（{3}），但{4}</translation>
        </message>
        <message>
            <source>{} is a folder, not a tool library (give the library's file)</source>
            <translation>{} 是文件夹，不是刀具库（请指定刀具库文件）</translation>
        </message>
        <message>
            <source>{} is not a regular file, not a tool library</source>
            <translation>{} 不是普通文件，不是刀具库</translation>
        </message>
        <message>
            <source>{} is empty, not a tool library (delete it to have the default library created)</source>
            <translation>{} 为空，不是刀具库（删除后将创建默认刀具库）</translation>
        </message>
        <message>
            <source>cannot create the folder of the tool library {}: {}</source>
            <translation>无法创建刀具库 {} 的文件夹：{}</translation>
        </message>
        <message>
            <source>{} was written by a newer Taiwa (tool library version {}); this program reads version {}</source>
            <translation>{} 由较新版本的 Taiwa 写入（刀具库版本 {}）；本程序只能读取版本 {}</translation>
        </message>
        <message>
            <source>{} is an SQLite database but not a tool library</source>
            <translation>{} 是 SQLite 数据库，但不是刀具库</translation>
        </message>
        <message>
            <source>{} (while upgrading it from tool library version {})</source>
            <translation>{}（从刀具库版本 {} 升级时）</translation>
        </message>
        <message>
            <source>{}: tool {}: {} is '{}', not a number</source>
            <translation>{}：刀具 {}：{} 为 '{}'，不是数字</translation>
        </message>
        <message>
            <source>{} is not a tool library (the file is not an SQLite database)</source>
            <translation>{} 不是刀具库（该文件不是 SQLite 数据库）</translation>
        </message>
        <message>
            <source>{} is locked by another program; close it and try again</source>
            <translation>{} 被其他程序锁定；请关闭该程序后重试</translation>
        </message>
        <message>
            <source>{} cannot be opened for writing ({})</source>
            <translation>无法以写入方式打开 {}（{}）</translation>
        </message>
        <message>
            <source>{} is damaged ({}); restore it from a backup</source>
            <translation>{} 已损坏（{}）；请从备份恢复</translation>
        </message>
        <message>
            <source>T{} ({:g} mm {}) reaches its life during step {} (unit {} {}): {:.1f} min left, the step needs {:.1f} min; change it for a fresh one before that step</source>
            <translation>T{0}（{1} mm {2}）将在工序 {3}（单元 {4} {5}）中达到寿命：剩余 {6} 分钟，该工序需要 {7} 分钟；请在该工序前换上新刀具</translation>
        </message>
        <message>
            <source>{}: tool {} has an unknown type '{}'</source>
            <translation>{}：刀具 {} 的类型 '{}' 未知</translation>
        </message>
        <message>
            <source>{}: tool {} has unreadable lathe data '{}'</source>
            <translation>{}：刀具 {} 的车削数据 '{}' 无法读取</translation>
        </message>
        <message>
            <source>allowance row {}: there is no edge {} in the profile</source>
            <translation>余量行 {}：轮廓中没有边 {}</translation>
        </message>
        <message>
            <source>allowance row {}: {} already has an allowance in row {}</source>
            <translation>余量行 {}：{} 已在第 {} 行有余量</translation>
        </message>
        <message>
            <source>allowance row {}: the allowance must be above zero</source>
            <translation>余量行 {}：余量必须大于零</translation>
        </message>
        <message>
            <source>allowance row {}: the adjustment cannot be below zero</source>
            <translation>余量行 {}：调整量不能小于零</translation>
        </message>
        <message>
            <source>allowance row {}: a groove width must be above zero</source>
            <translation>余量行 {}：槽宽必须大于零</translation>
        </message>
        <message>
            <source>allowance row {}: a groove depth must be above zero</source>
            <translation>余量行 {}：槽深必须大于零</translation>
        </message>
        <message>
            <source>the allowances and grooves split the part into {} pieces</source>
            <translation>余量和槽将零件分成 {} 块</translation>
        </message>
        <message>
            <source>internal: a piece of the deformed profile at Z{} X{} lies on no edge; please report this job</source>
            <translation>内部错误：变形轮廓在 Z{} X{} 处的一段不在任何边上；请报告此作业</translation>
        </message>
        <message>
            <source>allowance row {}: a {} groove at the corner of {} and {} would lie in {}, which has no grinding allowance; a relief groove only takes allowance off</source>
            <translation>余量行 {0}：位于 {2} 与 {3} 转角处的{1}槽将落在没有磨削余量的 {4} 上；退刀槽只去除余量</translation>
        </message>
        <message>
            <source>allowance row {}: a {} groove {} wide and {} deep takes {} of {}, which is {} long</source>
            <translation>余量行 {0}：宽 {2}、深 {3} 的{1}槽占去长 {6} 的 {5} 中的 {4}</translation>
        </message>
        <message>
            <source>allowance row {}: a groove {} deep at {} reaches the axis; it is deeper than the part allows</source>
            <translation>余量行 {0}：位于 {2} 的深 {1} 的槽达到轴线；比零件允许的更深</translation>
        </message>
        <message>
            <source>allowance row {}: a groove {} deep at {} reaches {}; it is deeper than the part allows</source>
            <translation>余量行 {0}：位于 {2} 的深 {1} 的槽达到 {3}；比零件允许的更深</translation>
        </message>
        <message>
            <source>allowance row {}: the moved {} and the moved {} do not meet</source>
            <translation>余量行 {}：偏移后的 {} 与偏移后的 {} 不相交</translation>
        </message>
        <message>
            <source>allowance row {}: {} meets {} at a tangent joint, where the tool's nose radius leaves a ridge; give the adjustment, or add a finishing turning tool to the library so that its nose radius is taken</source>
            <translation>余量行 {}：{} 与 {} 相切连接，刀尖半径会在此留下凸棱；请给出调整量，或在刀具库中添加精车刀以采用其刀尖半径</translation>
        </message>
        <message>
            <source>allowance row {}: an adjustment of {} is not shorter than {} ({} long)</source>
            <translation>余量行 {}：调整量 {} 不短于 {}（长 {}）</translation>
        </message>
        <message>
            <source>allowance row {}: the tangent of {} does not reach the moved {}</source>
            <translation>余量行 {}：{} 的切线达不到偏移后的 {}</translation>
        </message>
        <message>
            <source>allowance row {}: an allowance of {} on {} reaches past the end of its neighbour {} ({} long); the edges would cross</source>
            <translation>余量行 {0}：{2} 上 {1} 的余量超过相邻边 {3}（长 {4}）的端点；边会相交</translation>
        </message>
        <message>
            <source>allowance row {}: {} is an arc of radius {}; an allowance of {} leaves it no radius</source>
            <translation>余量行 {}：{} 是半径 {} 的圆弧；余量 {} 使其没有半径</translation>
        </message>
        <message>
            <source>allowance row {}: with an allowance of {} the moved {} vanishes between its neighbours; the edges would cross</source>
            <translation>余量行 {}：余量为 {} 时偏移后的 {} 在相邻边之间消失；边会相交</translation>
        </message>
        <message>
            <source>allowance row {}: an allowance of {} moves {} into {}; the edges would cross</source>
            <translation>余量行 {}：余量 {} 使 {} 移入 {}；边会相交</translation>
        </message>
        <message>
            <source>allowance row {}: an allowance of {} moves {} past the axis</source>
            <translation>余量行 {}：余量 {} 使 {} 越过轴线</translation>
        </message>
        <message>
            <source>row {} has the edge id {}, which is not a positive number of its own; every row needs one</source>
            <translation>第 {} 行的边编号 {} 不是唯一的正数；每行都需要一个</translation>
        </message>
        <message>
            <source>the start diameter is {}; a diameter cannot be below zero</source>
            <translation>起点直径为 {}；直径不能小于零</translation>
        </message>
        <message>
            <source>row {}: the end point is not a number</source>
            <translation>第 {} 行：终点不是数字</translation>
        </message>
        <message>
            <source>row {}: the end diameter is {}; a diameter cannot be below zero</source>
            <translation>第 {} 行：终点直径为 {}；直径不能小于零</translation>
        </message>
        <message>
            <source>row {} ends where it starts (X{} Z{}): an element needs a length</source>
            <translation>第 {} 行终点与起点相同（X{} Z{}）：元素需要有长度</translation>
        </message>
        <message>
            <source>row {}: the centre is {} from the start and {} from the end point; an arc's centre is equally far from both</source>
            <translation>第 {} 行：圆心距起点 {}、距终点 {}；圆弧圆心到两者距离应相等</translation>
        </message>
        <message>
            <source>row {}: the radius {} does not match the centre, which is {} from the start</source>
            <translation>第 {} 行：半径 {} 与圆心不符，圆心距起点 {}</translation>
        </message>
        <message>
            <source>row {}: an arc's radius must be above zero</source>
            <translation>第 {} 行：圆弧半径必须大于零</translation>
        </message>
        <message>
            <source>row {}: a radius of {} cannot reach the end point, which is {} from the start; the radius must be at least {}</source>
            <translation>第 {} 行：半径 {} 够不到距起点 {} 的终点；半径至少应为 {}</translation>
        </message>
        <message>
            <source>row {}: an arc needs its radius or its centre</source>
            <translation>第 {} 行：圆弧需要半径或圆心</translation>
        </message>
        <message>
            <source>row {}: the arc dips below the axis (to Ø{}); a turned profile stays at or above it</source>
            <translation>第 {} 行：圆弧低于轴线（到 Ø{}）；车削轮廓须在轴线上或以上</translation>
        </message>
        <message>
            <source>row {}: a {} needs a next row to meet; there is none</source>
            <translation>第 {} 行：{}需要与下一行相接；但没有下一行</translation>
        </message>
        <message>
            <source>row {}: a {} is made between two lines; row {} is an arc</source>
            <translation>第 {} 行：{}须在两条直线之间；第 {} 行是圆弧</translation>
        </message>
        <message>
            <source>row {}: the {} size must be above zero</source>
            <translation>第 {} 行：{}尺寸必须大于零</translation>
        </message>
        <message>
            <source>row {}: rows {} and {} are in line; there is no corner for a {}</source>
            <translation>第 {} 行：第 {} 行和第 {} 行共线；没有可加{}的角</translation>
        </message>
        <message>
            <source>row {}: a {} of {} takes {} of both lines; row {} has {} and row {} has {}</source>
            <translation>第 {0} 行：{2} 的{1}占用两条直线各 {3}；第 {4} 行长 {5}，第 {6} 行长 {7}</translation>
        </message>
        <message>
            <source>the profile is not one chain: {} (row {}) meets {} (row {}) at X{} Z{}</source>
            <translation>轮廓不是一条链：{}（第 {} 行）与 {}（第 {} 行）在 X{} Z{} 相交</translation>
        </message>
        <message>
            <source>the profile is not one chain around the part: {} (row {}) reaches the line closing it {} at X{} Z{}</source>
            <translation>轮廓不是围绕零件的一条链：{}（第 {} 行）在 X{} Z{} 处到达封闭线 {}</translation>
        </message>
        <message>
            <source>the job</source>
            <translation>作业</translation>
        </message>
        <message>
            <source>step {} ({}, unit {})</source>
            <translation>工序 {}（{}，单元 {}）</translation>
        </message>
        <message>
            <source>step {} ({}, unit {} '{}')</source>
            <translation>工序 {}（{}，单元 {} '{}'）</translation>
        </message>
        <message>
            <source>gouge {} deep into the finished part at {}, over {:.3f} mm² of the half-section</source>
            <translation>在 {1} 处切入成品 {0}，半剖面上面积 {2} mm²</translation>
        </message>
        <message>
            <source>gouge {} deep into the finished part at {}, over {:.3f} mm²</source>
            <translation>在 {1} 处切入成品 {0}，面积 {2} mm²</translation>
        </message>
        <message>
            <source>material left up to {} thicker than it should leave, thickest at {}, over {:.3f} mm² of the half-section</source>
            <translation>残留材料比应留量最多厚 {}，最厚处在 {}，半剖面上面积 {} mm²</translation>
        </message>
        <message>
            <source>material left up to {} above what it should leave, highest at {}, over {:.3f} mm²</source>
            <translation>残留材料比应留量最多高 {}，最高处在 {}，面积 {} mm²</translation>
        </message>
        <message>
            <source>the tool's {} runs {} into stock at {}</source>
            <translation>刀具的{0}在 {2} 处切入毛坯 {1}</translation>
        </message>
        <message>
            <source>rapid (G0) {} into stock at {}</source>
            <translation>快速移动（G0）在 {1} 处进入毛坯 {0}</translation>
        </message>
        <message>
            <source>the paths span {} more along {} than the machine '{}' travels</source>
            <translation>刀路沿 {1} 方向比机床 '{2}' 的行程多出 {0}</translation>
        </message>
        <message>
            <source>the tape has a {} the plan does not, to {}, {} into stock</source>
            <translation>程序带中有计划中没有的 {0}: 到 {1}，切入毛坯 {2}</translation>
        </message>
        <message>
            <source>the tape has a {} the plan does not, to {}</source>
            <translation>程序带中有计划中没有的 {0}: 到 {1}</translation>
        </message>
        <message>
            <source>the tape cannot be read back, so it is not verified from here on: {}</source>
            <translation>程序带无法读回，此后的部分未经验证: {0}</translation>
        </message>
        <message>
            <source>the wait {} is not met by the other path's program at its turn: both paths would stop there (a deadlock)</source>
            <translation>等待 {} 在另一路径的程序中没有同序的对应等待：两个路径都会停在这里（死锁）</translation>
        </message>
        <message>
            <source>{}: {}, in {} at line {}</source>
            <translation>{}：{}，{} 第 {} 行</translation>
        </message>
        <message>
            <source>{}: {}, move {}, tape line {}</source>
            <translation>{}：{}，移动 {}，程序第 {} 行</translation>
        </message>
        <message>
            <source>{}: {}, move {}</source>
            <translation>{}：{}，移动 {}</translation>
        </message>
        <message>
            <source>{}: {}, tape line {}</source>
            <translation>{}：{}，程序第 {} 行</translation>
        </message>
        <message>
            <source>holder</source>
            <translation>刀柄</translation>
        </message>
        <message>
            <source>shank</source>
            <translation>刀杆</translation>
        </message>
        <message>
            <source>verified at {:g} mm, not {:g} mm: on that grid the paths would have swept more than {:.3g} cells; --resolution {:g} verifies on it all the same</source>
            <translation>已按 {:g} mm 验证，而非 {:g} mm：在该网格上刀路扫过的单元将超过 {:.3g} 个；用 --resolution {:g} 仍可在该网格上验证</translation>
        </message>
        <message>
            <source>a lathe job with no turning step: nothing to cut</source>
            <translation>没有车削工步的车床作业: 无可切削</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::Diagnostic</name>
        <message>
            <source>%1: %2</source>
            <translation>%1：%2</translation>
        </message>
        <message>
            <source>unit</source>
            <translation>单元</translation>
        </message>
        <message>
            <source>%1: job %2: warning: %3</source>
            <translation>%1：作业 %2：警告：%3</translation>
        </message>
        <message>
            <source>%1: job %2: %3</source>
            <translation>%1：作业 %2：%3</translation>
        </message>
        <message>
            <source>%1: unit %2 (%3) %4: warning: %5</source>
            <translation>%1：单元 %2（%3）%4：警告：%5</translation>
        </message>
        <message>
            <source>%1: unit %2 (%3) %4: %5</source>
            <translation>%1：单元 %2（%3）%4：%5</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::TechnologyDialog</name>
        <message>
            <source>pilot hole stops this far above the floor</source>
            <translation>预钻孔在底面以上此距离处停止</translation>
        </message>
        <message>
            <source>wall allowance left by roughing</source>
            <translation>粗加工留下的侧壁余量</translation>
        </message>
        <message>
            <source>wall allowance of the semi-finish pass (F = 3)</source>
            <translation>半精加工的侧壁余量 (F = 3)</translation>
        </message>
        <message>
            <source>floor allowance left by roughing</source>
            <translation>粗加工留下的底面余量</translation>
        </message>
        <message>
            <source>roughing layer depth / tool diameter</source>
            <translation>粗加工层深 / 刀具直径</translation>
        </message>
        <message>
            <source>roughing step-over / tool diameter</source>
            <translation>粗加工行距 / 刀具直径</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::ModulePalette</name>
        <message>
            <source>Add drawn-pass area</source>
            <translation>添加绘制路径区域加工</translation>
        </message>
        <message>
            <source>Add contour pocket</source>
            <translation>添加轮廓型腔</translation>
        </message>
        <message>
            <source>Add face milling</source>
            <translation>添加面铣</translation>
        </message>
        <message>
            <source>Add hole pattern</source>
            <translation>添加孔组</translation>
        </message>
        <message>
            <source>Add M2D 3-D pocket</source>
            <translation>添加 M2D 三维型腔</translation>
        </message>
        <message>
            <source>Add M4 pocket</source>
            <translation>添加 M4 型腔</translation>
        </message>
        <message>
            <source>Add work-centre probing</source>
            <translation>添加工件中心测量</translation>
        </message>
        <message>
            <source>Add side milling</source>
            <translation>添加侧铣</translation>
        </message>
        <message>
            <source>Add 3-D surface</source>
            <translation>添加三维曲面</translation>
        </message>
        <message>
            <source>Add turned profile</source>
            <translation>添加车削轮廓</translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::FieldSpec</name>
        <message>
            <source>r1 (corner radius)</source>
            <translation>r1(拐角半径)</translation>
        </message>
        <message>
            <source>Radius of the pocket's corners; the finishing end mill must fit in it</source>
            <translation>型腔拐角半径；精加工立铣刀必须能放入</translation>
        </message>
        <message>
            <source>T (depth)</source>
            <translation>T(深度)</translation>
        </message>
        <message>
            <source>Depth of the pocket, down from the top surface</source>
            <translation>型腔深度，从上表面向下</translation>
        </message>
        <message>
            <source>U (tool use)</source>
            <translation>U(刀具使用)</translation>
        </message>
        <message>
            <source>Which steps the pocket gets: roughing, floor and wall finishing, or some of them</source>
            <translation>型腔的工步：粗加工、底面和侧壁精加工，或其中一部分</translation>
        </message>
        <message>
            <source>F (wall finish)</source>
            <translation>F(侧壁精加工)</translation>
        </message>
        <message>
            <source>How the walls are finished: at full depth, in several depths, or in two stages</source>
            <translation>侧壁的精加工方式：一次到全深、分层或分两阶段</translation>
        </message>
        <message>
            <source>H (pilot hole)</source>
            <translation>H(预钻孔)</translation>
        </message>
        <message>
            <source>Whether a hole is drilled first for the roughing end mill to go down into</source>
            <translation>是否先钻孔，供粗加工立铣刀下刀</translation>
        </message>
        <message>
            <source>Step-over (× D)</source>
            <translation>行距 (× D)</translation>
        </message>
        <message>
            <source>technology data's</source>
            <translation>工艺数据的值</translation>
        </message>
        <message>
            <source>Roughing's sideways step as a share of the tool's diameter; empty for the technology data's</source>
            <translation>粗加工的横向步距，占刀具直径的比例；空表示使用工艺数据的值</translation>
        </message>
        <message>
            <source>Islands</source>
            <translation>岛</translation>
        </message>
        <message>
            <source>Area</source>
            <translation>区域</translation>
        </message>
        <message>
            <source>The contour of the figure around the area to clear (e.g. K1)</source>
            <translation>围绕待清除区域的图形轮廓（例如 K1）</translation>
        </message>
        <message>
            <source>Contours of the figure left standing in the area, separated by commas; empty for none</source>
            <translation>区域内保留的图形轮廓，用逗号分隔；无则留空</translation>
        </message>
        <message>
            <source>Depth the passes cut to, down from the top surface</source>
            <translation>路径切削的深度（自上表面向下）</translation>
        </message>
        <message>
            <source>D (tool diameter)</source>
            <translation>D（刀具直径）</translation>
        </message>
        <message>
            <source>Diameter of the end mill: each pass is a strip this wide</source>
            <translation>立铣刀直径：每条路径为此宽度的条带</translation>
        </message>
        <message>
            <source>Passes (points)</source>
            <translation>路径（点）</translation>
        </message>
        <message>
            <source>The passes as points X, Y separated by ';' (the tool goes from each to the next); draw them in the Figure tab</source>
            <translation>以 ';' 分隔的点 X, Y 表示路径（刀具从一点走到下一点）；也可在图形页中绘制</translation>
        </message>
        <message>
            <source>Outline</source>
            <translation>轮廓</translation>
        </message>
        <message>
            <source>The contour of the figure that is the pocket's edge at the top (e.g. K1)</source>
            <translation>作为型腔顶面边缘的图形轮廓（例如 K1）</translation>
        </message>
        <message>
            <source>Contours of the figure left standing in the pocket, separated by commas (e.g. K2, K3); empty for none</source>
            <translation>型腔中保留的岛的图形轮廓，用逗号分隔（例如 K2, K3）；无则留空</translation>
        </message>
        <message>
            <source>Depth</source>
            <translation>深度</translation>
        </message>
        <message>
            <source>Stock taken off the top, down from Z0; less than the stock's height</source>
            <translation>从顶面去除的量（自 Z0 向下）；小于毛坯高度</translation>
        </message>
        <message>
            <source>Roughing layers and a finishing pass (1), or roughing only leaving the finishing pass (9)</source>
            <translation>粗加工层加精加工刀路（1），或仅粗加工并留出精加工余量（9）</translation>
        </message>
        <message>
            <source>Finishing pass</source>
            <translation>精加工刀路</translation>
        </message>
        <message>
            <source>technology data's β2</source>
            <translation>工艺数据的 β2</translation>
        </message>
        <message>
            <source>Depth of the finishing pass, less than the depth; empty for the technology data's β2</source>
            <translation>精加工刀路的深度，小于总深度；留空则为工艺数据的 β2</translation>
        </message>
        <message>
            <source>Angle of the passes (°)</source>
            <translation>刀路角度（°）</translation>
        </message>
        <message>
            <source>Direction of the passes in degrees, counter-clockwise from +X</source>
            <translation>刀路方向，自 +X 逆时针的角度</translation>
        </message>
        <message>
            <source>Pattern</source>
            <translation>排列方式</translation>
        </message>
        <message>
            <source>One way (every pass climb, back above the part) or zigzag (back and forth, linked beside the part)</source>
            <translation>单向（每条刀路顺铣，在工件上方返回）或之字形（往复，在工件外侧连接）</translation>
        </message>
        <message>
            <source>0.75 (face mill), else technology data's</source>
            <translation>0.75（面铣刀），否则为工艺数据值</translation>
        </message>
        <message>
            <source>Distance between passes as a share of the tool's diameter, above 0 and at most 0.9</source>
            <translation>刀路间距占刀具直径的比例，大于 0 且不超过 0.9</translation>
        </message>
        <message>
            <source>Margin beyond the stock</source>
            <translation>超出毛坯的余量</translation>
        </message>
        <message>
            <source>How far the face reaches beyond the stock's sides; 0 for exactly the top</source>
            <translation>面铣范围超出毛坯侧面的距离；0 表示恰好为顶面</translation>
        </message>
        <message>
            <source>How the holes are laid out: one hole, a line, a grid, a bolt circle or an arc</source>
            <translation>孔的排列方式：单孔、直线、网格、螺栓圆或圆弧</translation>
        </message>
        <message>
            <source>X (hole, first hole or centre)</source>
            <translation>X（孔、第一个孔或中心）</translation>
        </message>
        <message>
            <source>The hole, the first hole of a line, the corner of a grid, the centre of a circle</source>
            <translation>单孔、直线的第一个孔、网格的角点、圆的中心</translation>
        </message>
        <message>
            <source>Y of the hole, the first hole of a line, the corner of a grid, the centre of a circle</source>
            <translation>孔、直线第一个孔、网格角点或圆心的 Y</translation>
        </message>
        <message>
            <source>Angle (°)</source>
            <translation>角度 (°)</translation>
        </message>
        <message>
            <source>Direction of a line's or grid's rows; angle of a circle's first hole</source>
            <translation>直线或网格各行的方向；圆上第一个孔的角度</translation>
        </message>
        <message>
            <source>Pitch</source>
            <translation>间距</translation>
        </message>
        <message>
            <source>Distance between neighbouring holes along the row</source>
            <translation>沿行相邻孔之间的距离</translation>
        </message>
        <message>
            <source>Pitch between rows</source>
            <translation>行间距</translation>
        </message>
        <message>
            <source>Grid: distance between rows</source>
            <translation>网格：行与行的间距</translation>
        </message>
        <message>
            <source>Radius</source>
            <translation>半径</translation>
        </message>
        <message>
            <source>Bolt circle or arc: the radius the hole centres lie on</source>
            <translation>螺栓圆或圆弧:孔中心所在的半径</translation>
        </message>
        <message>
            <source>Angular pitch (°)</source>
            <translation>角度间距 (°)</translation>
        </message>
        <message>
            <source>Arc: angle between neighbouring holes</source>
            <translation>圆弧：相邻孔之间的角度</translation>
        </message>
        <message>
            <source>Count (grid: columns)</source>
            <translation>数量（网格：列数）</translation>
        </message>
        <message>
            <source>How many holes: along a line, around a circle or an arc; a grid's columns</source>
            <translation>孔数:沿直线、圆周或圆弧;网格为列数</translation>
        </message>
        <message>
            <source>Rows</source>
            <translation>行数</translation>
        </message>
        <message>
            <source>Grid: how many rows of holes</source>
            <translation>网格:孔的行数</translation>
        </message>
        <message>
            <source>Hole</source>
            <translation>孔</translation>
        </message>
        <message>
            <source>Drilled, tapped, reamed or bored: which steps each hole gets</source>
            <translation>钻孔、攻丝、铰孔或镗孔：每个孔的加工工步</translation>
        </message>
        <message>
            <source>Thread (tapped)</source>
            <translation>螺纹（攻丝）</translation>
        </message>
        <message>
            <source>Tapped holes: the ISO metric coarse thread, M3 to M20</source>
            <translation>螺纹孔:ISO 公制粗牙螺纹 M3 至 M20</translation>
        </message>
        <message>
            <source>Diameter</source>
            <translation>直径</translation>
        </message>
        <message>
            <source>Diameter of a drilled, reamed or bored hole (a tapped hole takes its thread's)</source>
            <translation>钻孔、铰孔或镗孔的直径(螺纹孔取螺纹的直径)</translation>
        </message>
        <message>
            <source>Depth (full diameter)</source>
            <translation>深度（全直径部分）</translation>
        </message>
        <message>
            <source>Depth of the full diameter (of the full thread), down from the top; the drill point goes deeper</source>
            <translation>全直径（完整螺纹）部分的深度，从顶面向下；钻尖会更深</translation>
        </message>
        <message>
            <source>The corner where the opening starts, at the top surface, in work coordinates</source>
            <translation>开口起始的角点，位于上表面，工件坐标</translation>
        </message>
        <message>
            <source>L1 (length X)</source>
            <translation>L1(X 向长度)</translation>
        </message>
        <message>
            <source>Length of the opening along X, at the top surface</source>
            <translation>开口沿 X 的长度（上表面）</translation>
        </message>
        <message>
            <source>L2 (length Y)</source>
            <translation>L2(Y 向长度)</translation>
        </message>
        <message>
            <source>Width of the opening along Y, at the top surface</source>
            <translation>开口沿 Y 的宽度（上表面）</translation>
        </message>
        <message>
            <source>θ1 (left wall, °)</source>
            <translation>θ1(左壁,°)</translation>
        </message>
        <message>
            <source>Slope of the wall at the start of L1, in degrees from the vertical</source>
            <translation>L1 起始端侧壁的倾角（相对竖直方向，度）</translation>
        </message>
        <message>
            <source>θ2 (right wall, °)</source>
            <translation>θ2(右壁,°)</translation>
        </message>
        <message>
            <source>empty = same as θ1</source>
            <translation>空 = 与 θ1 相同</translation>
        </message>
        <message>
            <source>Slope of the wall at the end of L1, in degrees from the vertical; empty for the same as θ1</source>
            <translation>L1 末端侧壁的倾角（相对竖直方向，度）；空表示与 θ1 相同</translation>
        </message>
        <message>
            <source>Scallop height</source>
            <translation>残留高度</translation>
        </message>
        <message>
            <source>Largest ridge the ball end mill may leave between its passes on the inclined walls</source>
            <translation>球头铣刀在斜壁上两道刀路之间允许留下的最大残留高度</translation>
        </message>
        <message>
            <source>A corner of the pocket at the top surface, in work coordinates</source>
            <translation>型腔在上表面的角点（工件坐标）</translation>
        </message>
        <message>
            <source>S (taper, °/side)</source>
            <translation>S(斜度,单边 °)</translation>
        </message>
        <message>
            <source>Slope of the walls in degrees per side; 0 for vertical walls</source>
            <translation>侧壁斜度（单边，度）；竖直侧壁为 0</translation>
        </message>
        <message>
            <source>Shape</source>
            <translation>形状</translation>
        </message>
        <message>
            <source>Round (a boss or a bore) or rectangular (a block or a pocket)</source>
            <translation>圆形（凸台或孔）或矩形（块或型腔）</translation>
        </message>
        <message>
            <source>Touched from</source>
            <translation>接触方向</translation>
        </message>
        <message>
            <source>Whether the probe touches the part from outside or from inside</source>
            <translation>测头从外侧还是内侧接触工件</translation>
        </message>
        <message>
            <source>P1 machine X</source>
            <translation>P1 机床坐标 X</translation>
        </message>
        <message>
            <source>Where the first touch is, in machine coordinates</source>
            <translation>第一个测量点的位置（机床坐标）</translation>
        </message>
        <message>
            <source>P1 machine Y</source>
            <translation>P1 机床坐标 Y</translation>
        </message>
        <message>
            <source>not touched</source>
            <translation>未测量</translation>
        </message>
        <message>
            <source>A touch, relative to the first one; empty until it is measured</source>
            <translation>相对第一个点的测量点；测量前为空</translation>
        </message>
        <message>
            <source>P2 side</source>
            <translation>P2 面</translation>
        </message>
        <message>
            <source>P3 side</source>
            <translation>P3 面</translation>
        </message>
        <message>
            <source>P4 side</source>
            <translation>P4 面</translation>
        </message>
        <message>
            <source>P5 side</source>
            <translation>P5 面</translation>
        </message>
        <message>
            <source>P6 side</source>
            <translation>P6 面</translation>
        </message>
        <message>
            <source>P7 side</source>
            <translation>P7 面</translation>
        </message>
        <message>
            <source>P8 side</source>
            <translation>P8 面</translation>
        </message>
        <message>
            <source>Top face machine Z</source>
            <translation>顶面 机床坐标 Z</translation>
        </message>
        <message>
            <source>Height of a touch on the top face, in machine coordinates; empty if not touched</source>
            <translation>顶面测量点的高度（机床坐标）；不测量则为空</translation>
        </message>
        <message>
            <source>Tolerance</source>
            <translation>公差</translation>
        </message>
        <message>
            <source>Largest distance a touch may lie from the fitted shape</source>
            <translation>测量点离拟合形状允许的最大距离</translation>
        </message>
        <message>
            <source>Nominal diameter / width X</source>
            <translation>公称直径 / X 向宽度</translation>
        </message>
        <message>
            <source>Diameter of the round part, or its width along X</source>
            <translation>圆形工件的直径，或沿 X 的宽度</translation>
        </message>
        <message>
            <source>Nominal length Y</source>
            <translation>公称长度 Y</translation>
        </message>
        <message>
            <source>Length of the rectangular part along Y</source>
            <translation>矩形工件沿 Y 的长度</translation>
        </message>
        <message>
            <source>Touch depth</source>
            <translation>接触深度</translation>
        </message>
        <message>
            <source>How far below the top face the probe touches the sides</source>
            <translation>测量侧面时距顶面的深度</translation>
        </message>
        <message>
            <source>Clearance</source>
            <translation>安全距离</translation>
        </message>
        <message>
            <source>Distance kept from the part while the probe moves between touches</source>
            <translation>测量点之间移动时与工件保持的距离</translation>
        </message>
        <message>
            <source>Search distance</source>
            <translation>搜索距离</translation>
        </message>
        <message>
            <source>How far past the expected surface the probe looks for it before giving up</source>
            <translation>越过预期表面继续寻找的距离，找不到则停止</translation>
        </message>
        <message>
            <source>Probing feed (mm/min)</source>
            <translation>测量进给 (mm/min)</translation>
        </message>
        <message>
            <source>Feed of the probing moves, in mm per minute</source>
            <translation>测量移动的进给（mm/min）</translation>
        </message>
        <message>
            <source>Contour</source>
            <translation>轮廓</translation>
        </message>
        <message>
            <source>The contour of the figure that is the finished wall, open or closed (e.g. K1)</source>
            <translation>作为完成壁面的图形轮廓，可开放或闭合（例如 K1）</translation>
        </message>
        <message>
            <source>Tool side</source>
            <translation>刀具侧</translation>
        </message>
        <message>
            <source>Which side of the contour, looking along its direction, the tool and the material to remove are on</source>
            <translation>沿轮廓方向看，刀具和待去除材料位于哪一侧</translation>
        </message>
        <message>
            <source>Direction</source>
            <translation>方向</translation>
        </message>
        <message>
            <source>Climb or conventional milling (with M3, climb runs the tool on the left of its travel)</source>
            <translation>顺铣或逆铣（M3 时，顺铣刀具位于行进方向左侧）</translation>
        </message>
        <message>
            <source>Depth of the wall, down from the top surface</source>
            <translation>壁深度（自上表面向下）</translation>
        </message>
        <message>
            <source>W (width)</source>
            <translation>W（宽度）</translation>
        </message>
        <message>
            <source>Width of the material to remove, measured from the contour on the tool's side</source>
            <translation>待去除材料的宽度，从刀具一侧的轮廓量起</translation>
        </message>
        <message>
            <source>Which steps the wall gets: roughing and finishing, or one of them</source>
            <translation>壁的工序：粗加工和精加工，或其中之一</translation>
        </message>
        <message>
            <source>How the wall is finished: at full depth, or in several depths</source>
            <translation>壁的精加工方式：全深度一次，或分几层深度</translation>
        </message>
        <message>
            <source>Curve 1</source>
            <translation>曲线 1</translation>
        </message>
        <message>
            <source>the surface is a STEP face set</source>
            <translation>曲面为 STEP 面集</translation>
        </message>
        <message>
            <source>The first curve: points X, Y, Z separated by ';', or two projections 'XY: X, Y; ... / ZX: Z, X; ...', each its points or an open contour of the figure ('XY: K1'); '/ lines' at the end for straight lines</source>
            <translation>第一条曲线: 以 ';' 分隔的点 X, Y, Z，或两个投影 'XY: X, Y; ... / ZX: Z, X; ...'（每个投影为点列或图形的开放轮廓 'XY: K1'）；末尾加 '/ lines' 表示以直线连接</translation>
        </message>
        <message>
            <source>Curve 2</source>
            <translation>曲线 2</translation>
        </message>
        <message>
            <source>The second curve, as the first; the surface is ruled between the two</source>
            <translation>第二条曲线, 写法同第一条; 曲面是两条曲线之间的直纹面</translation>
        </message>
        <message>
            <source>N (roughing pieces)</source>
            <translation>N (粗加工分段数)</translation>
        </message>
        <message>
            <source>Pieces each curve is divided into for the roughing surface; fewer than M</source>
            <translation>为粗加工曲面将每条曲线分成的段数; 少于 M</translation>
        </message>
        <message>
            <source>M (finishing pieces)</source>
            <translation>M (精加工分段数)</translation>
        </message>
        <message>
            <source>Pieces each curve is divided into for the finishing surface; more than N; empty: from the step along the curves</source>
            <translation>为精加工曲面将每条曲线分成的段数; 多于 N; 空: 由沿曲线的步距决定</translation>
        </message>
        <message>
            <source>Step along the curves (gives M)</source>
            <translation>沿曲线的步距 (决定 M)</translation>
        </message>
        <message>
            <source>M given</source>
            <translation>已给出 M</translation>
        </message>
        <message>
            <source>The step along the curves that gives M; empty when M is given</source>
            <translation>决定 M 的沿曲线步距; 给出 M 时为空</translation>
        </message>
        <message>
            <source>Height of the ridges the ball leaves between finishing paths</source>
            <translation>精加工路径之间球头留下的残留高度</translation>
        </message>
        <message>
            <source>Roughing allowance</source>
            <translation>粗加工余量</translation>
        </message>
        <message>
            <source>Material the Z-level roughing leaves on the surface, along its normal</source>
            <translation>等高粗加工沿法向在曲面上留下的材料</translation>
        </message>
        <message>
            <source>Boundary (paths)</source>
            <translation>边界 (路径)</translation>
        </message>
        <message>
            <source>none: the whole surface</source>
            <translation>无: 整个曲面</translation>
        </message>
        <message>
            <source>A surface where every path stops: paths of points X, Y, Z, ';' between points, '/' between paths; empty for none</source>
            <translation>每条路径停止处的曲面: 由点 X, Y, Z 组成的路径, 点之间用 ';', 路径之间用 '/'; 无则为空</translation>
        </message>
        <message>
            <source>Ball end mill (T)</source>
            <translation>球头立铣刀 (T)</translation>
        </message>
        <message>
            <source>under the smallest concave radius</source>
            <translation>小于最小凹半径</translation>
        </message>
        <message>
            <source>The ball end mill's number in the tool library; empty: the largest whose radius is under the smallest concave radius</source>
            <translation>刀具库中球头立铣刀的编号; 空: 半径小于最小凹半径的最大刀具</translation>
        </message>
        <message>
            <source>Profile</source>
            <translation>轮廓</translation>
        </message>
        <message>
            <source>Outer profile (the outside diameter) or inner profile (a bore)</source>
            <translation>外轮廓（外径）或内轮廓（孔）</translation>
        </message>
        <message>
            <source>Start X (diameter)</source>
            <translation>起点 X (直径)</translation>
        </message>
        <message>
            <source>Diameter where the profile starts, at its front end</source>
            <translation>轮廓起点的直径（前端）</translation>
        </message>
        <message>
            <source>Start Z</source>
            <translation>起点 Z</translation>
        </message>
        <message>
            <source>Z where the profile starts; 0 is the finished front face</source>
            <translation>轮廓起点的 Z；0 为精加工后的前端面</translation>
        </message>
    </context>
    <context>
        <name>taiwa::Drawing</name>
        <message>
            <source>AREA – top view</source>
            <translation>AREA – 俯视图</translation>
        </message>
        <message>
            <source>Pn</source>
            <translation>Pn</translation>
        </message>
        <message>
            <source>passes</source>
            <translation>刀路</translation>
        </message>
        <message>
            <source>section</source>
            <translation>剖面</translation>
        </message>
        <message>
            <source>CP – top view</source>
            <translation>CP – 俯视图</translation>
        </message>
        <message>
            <source>outline K1, islands K2, K3: CONTOURs</source>
            <translation>外轮廓 K1，岛屿 K2, K3：CONTOUR</translation>
        </message>
        <message>
            <source>FACE – top view</source>
            <translation>FACE – 俯视图</translation>
        </message>
        <message>
            <source>margin</source>
            <translation>外延</translation>
        </message>
        <message>
            <source>angle</source>
            <translation>角度</translation>
        </message>
        <message>
            <source>depth</source>
            <translation>深度</translation>
        </message>
        <message>
            <source>finish</source>
            <translation>精加工</translation>
        </message>
        <message>
            <source>HOLES – top view</source>
            <translation>HOLES – 俯视图</translation>
        </message>
        <message>
            <source>M2D – top view</source>
            <translation>M2D – 俯视图</translation>
        </message>
        <message>
            <source>section along L1</source>
            <translation>沿 L1 的剖面</translation>
        </message>
        <message>
            <source>M4 – top view</source>
            <translation>M4 – 俯视图</translation>
        </message>
        <message>
            <source>X, Y of P1…P4</source>
            <translation>P1…P4 的 X, Y</translation>
        </message>
        <message>
            <source>round – top view</source>
            <translation>圆形 – 俯视图</translation>
        </message>
        <message>
            <source>centre</source>
            <translation>中心</translation>
        </message>
        <message>
            <source>rectangular – top view</source>
            <translation>矩形 – 俯视图</translation>
        </message>
        <message>
            <source>-Y (twice)</source>
            <translation>-Y（两次）</translation>
        </message>
        <message>
            <source>SIDE – top view</source>
            <translation>SIDE – 俯视图</translation>
        </message>
        <message>
            <source>climb</source>
            <translation>顺铣</translation>
        </message>
        <message>
            <source>side 1: the tool left of K1's direction</source>
            <translation>侧 1：刀具在 K1 方向左侧</translation>
        </message>
        <message>
            <source>half-section: Z →, X (diameter) ↑</source>
            <translation>半剖面：Z →，X（直径）↑</translation>
        </message>
        <message>
            <source>start X0 Z0</source>
            <translation>起点 X0 Z0</translation>
        </message>
    </context>
</TS>
