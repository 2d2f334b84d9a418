<?xml version="1.0" encoding="utf-8"?>
<!-- Texts of the station window (lupdate from ui/ and core/modules/ by resources/i18n/update-ts.py, translated by hand); compiled to .qm by lrelease at build time. -->
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
        <name>taiwa::ui::FigurePanel</name>
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
            <source>Export into folder</source>
            <translation>导出到文件夹</translation>
        </message>
        <message>
            <source>Controller dialect</source>
            <translation>数控系统格式</translation>
        </message>
        <message>
            <source>Export failed</source>
            <translation>导出失败</translation>
        </message>
        <message>
            <source>Exported %1 files into %2</source>
            <translation>已将 %1 个文件导出到 %2</translation>
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
            <source>mm</source>
            <translation>mm</translation>
        </message>
        <message>
            <source>inch (converts every length)</source>
            <translation>英寸(换算所有长度)</translation>
        </message>
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
            <source>Machine %1</source>
            <translation>机床 %1</translation>
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
            <source>Clamping</source>
            <translation>装夹</translation>
        </message>
        <message>
            <source>Jaws' height</source>
            <translation>钳口高度</translation>
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
            <source>&amp;NC program, dialect:</source>
            <translation>NC 程序(&amp;N),数控系统:</translation>
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
            <source>Remove the last point of the passes</source>
            <translation>删除路径的最后一点</translation>
        </message>
        <message>
            <source>Clear the passes</source>
            <translation>清除路径</translation>
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
            <source>Profile, in cutting order (X is a diameter; arcs: R, or the centre)</source>
            <translation>轮廓,按切削顺序(X 为直径;圆弧:R 或圆心)</translation>
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
            <source>Grinding allowance per edge (empty: adjustment from the finishing tool's nose radius, depth = allowance, no width = no groove)</source>
            <translation>各边的磨削余量(空:调整量取精加工刀具的刀尖圆弧半径,深度 = 余量,无宽度 = 无槽)</translation>
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
            <source>Element of row %1</source>
            <translation>第 %1 行的元素</translation>
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
            <source>Corner of row %1</source>
            <translation>第 %1 行的拐角</translation>
        </message>
        <message>
            <source>Groove kind of allowance %1</source>
            <translation>余量 %1 的槽类型</translation>
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
            <source>Chamfer %1: leg</source>
            <translation>倒角 %1:边长</translation>
        </message>
        <message>
            <source>Rounding %1: radius</source>
            <translation>圆角 %1:半径</translation>
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
            <source>Tool library: %1 (using the built-in library)</source>
            <translation>刀具库:%1(使用内置刀具库)</translation>
        </message>
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
            <source>Unit</source>
            <translation>单元</translation>
        </message>
        <message>
            <source>3-D view</source>
            <translation>3D 视图</translation>
        </message>
        <message>
            <source>No 3-D preview: this display has no OpenGL.</source>
            <translation>无 3D 预览:此显示器不支持 OpenGL。</translation>
        </message>
        <message>
            <source>Figure</source>
            <translation>图形</translation>
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
            <source>&amp;Language</source>
            <translation>语言(&amp;L)</translation>
        </message>
        <message>
            <source>The language changes when Taiwa is started again.</source>
            <translation>语言将在 Taiwa 下次启动时切换。</translation>
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
            <source>Edit %1 of unit %2</source>
            <translation>编辑单元 %2 的 %1</translation>
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
        <message>
            <source>DXF contours become figure elements, which a lathe job does not use.</source>
            <translation>DXF 轮廓会成为图形元素，而车削作业不使用图形元素。</translation>
        </message>
        <message>
            <source>Import DXF contours</source>
            <translation>导入 DXF 轮廓</translation>
        </message>
        <message>
            <source>Not up to date: the job has input errors. The 3-D view and the NC program show the last valid job. First error: %1</source>
            <translation>不是最新:作业有输入错误。3D 视图和 NC 程序显示的是最后一个有效作业。第一个错误:%1</translation>
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
        <message>
            <source>untitled</source>
            <translation>未命名</translation>
        </message>
        <message numerus="yes">
            <source>%1 is also open in %n other window(s): a save here asks before it overwrites what another window saved.</source>
            <translation>
                <numerusform>%1 也在其他 %n 个窗口中打开:在此保存时,覆盖其他窗口保存的内容前会先询问。</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::StepPanel</name>
        <message>
            <source>&amp;Stock</source>
            <translation>毛坯(&amp;S)</translation>
        </message>
        <message>
            <source>&amp;Before step</source>
            <translation>工步之前(&amp;B)</translation>
        </message>
        <message>
            <source>▶ Pla&amp;y</source>
            <translation>▶ 播放(&amp;Y)</translation>
        </message>
        <message>
            <source>The stock as the simulation cuts it, instead of a glass block</source>
            <translation>显示仿真切削后的毛坯,而不是玻璃块</translation>
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
            <source>■ Stop (&amp;Y)</source>
            <translation>■ 停止(&amp;Y)</translation>
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
            <source>Cannot open the tool library: %1</source>
            <translation>无法打开刀具库：%1</translation>
        </message>
        <message>
            <source>Cannot save the tool: %1</source>
            <translation>无法保存刀具:%1</translation>
        </message>
        <message>
            <source>Cannot retire the tool: %1</source>
            <translation>无法报废刀具：%1</translation>
        </message>
        <message>
            <source>T%1 not saved: %2</source>
            <translation>T%1 未保存：%2</translation>
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
            <source>Colour &amp;map</source>
            <translation>色彩图(&amp;M)</translation>
        </message>
        <message>
            <source>Cut every step into the stock on a %1 mm grid and list gouges, collisions, rapids into stock, travel limits and material left</source>
            <translation>以 %1 mm 网格将所有工步切入毛坯，列出过切、碰撞、快移撞入毛坯、超出行程和残料</translation>
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
            <source>Not verified since the last change.</source>
            <translation>自上次修改后尚未验证。</translation>
        </message>
        <message>
            <source>No plan to verify.</source>
            <translation>没有可验证的加工计划。</translation>
        </message>
        <message>
            <source>Verifying…</source>
            <translation>正在验证…</translation>
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
    </context>
    <context>
        <name>taiwa::ui::FieldSpec</name>
        <message>
            <source>Area</source>
            <translation>区域</translation>
        </message>
        <message>
            <source>Islands</source>
            <translation>岛</translation>
        </message>
        <message>
            <source>T (depth)</source>
            <translation>T(深度)</translation>
        </message>
        <message>
            <source>D (tool diameter)</source>
            <translation>D（刀具直径）</translation>
        </message>
        <message>
            <source>Passes (points)</source>
            <translation>路径（点）</translation>
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
            <source>Diameter of the end mill: each pass is a strip this wide</source>
            <translation>立铣刀直径：每条路径为此宽度的条带</translation>
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
            <source>U (tool use)</source>
            <translation>U(刀具使用)</translation>
        </message>
        <message>
            <source>F (wall finish)</source>
            <translation>F(侧壁精加工)</translation>
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
            <source>Depth of the pocket, down from the top surface</source>
            <translation>型腔深度，从上表面向下</translation>
        </message>
        <message>
            <source>Which steps the pocket gets: roughing, floor and wall finishing, or some of them</source>
            <translation>型腔的工步：粗加工、底面和侧壁精加工，或其中一部分</translation>
        </message>
        <message>
            <source>How the walls are finished: at full depth, in several depths, or in two stages</source>
            <translation>侧壁的精加工方式：一次到全深、分层或分两阶段</translation>
        </message>
        <message>
            <source>Roughing's sideways step as a share of the tool's diameter; empty for the technology data's</source>
            <translation>粗加工的横向步距，占刀具直径的比例；空表示使用工艺数据的值</translation>
        </message>
        <message>
            <source>Depth</source>
            <translation>深度</translation>
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
            <source>Angle of the passes (°)</source>
            <translation>刀路角度（°）</translation>
        </message>
        <message>
            <source>Pattern</source>
            <translation>排列方式</translation>
        </message>
        <message>
            <source>Step-over (× D)</source>
            <translation>行距 (× D)</translation>
        </message>
        <message>
            <source>0.75 (face mill), else technology data's</source>
            <translation>0.75（面铣刀），否则为工艺数据值</translation>
        </message>
        <message>
            <source>Margin beyond the stock</source>
            <translation>超出毛坯的余量</translation>
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
            <source>Depth of the finishing pass, less than the depth; empty for the technology data's β2</source>
            <translation>精加工刀路的深度，小于总深度；留空则为工艺数据的 β2</translation>
        </message>
        <message>
            <source>Direction of the passes in degrees, counter-clockwise from +X</source>
            <translation>刀路方向，自 +X 逆时针的角度</translation>
        </message>
        <message>
            <source>One way (every pass climb, back above the part) or zigzag (back and forth, linked beside the part)</source>
            <translation>单向（每条刀路顺铣，在工件上方返回）或之字形（往复，在工件外侧连接）</translation>
        </message>
        <message>
            <source>Distance between passes as a share of the tool's diameter, above 0 and at most 0.9</source>
            <translation>刀路间距占刀具直径的比例，大于 0 且不超过 0.9</translation>
        </message>
        <message>
            <source>How far the face reaches beyond the stock's sides; 0 for exactly the top</source>
            <translation>面铣范围超出毛坯侧面的距离；0 表示恰好为顶面</translation>
        </message>
        <message>
            <source>technology data's</source>
            <translation>工艺数据的值</translation>
        </message>
        <message>
            <source>X (hole, first hole or centre)</source>
            <translation>X（孔、第一个孔或中心）</translation>
        </message>
        <message>
            <source>Y</source>
            <translation>Y</translation>
        </message>
        <message>
            <source>Angle (°)</source>
            <translation>角度 (°)</translation>
        </message>
        <message>
            <source>Pitch</source>
            <translation>间距</translation>
        </message>
        <message>
            <source>Pitch between rows</source>
            <translation>行间距</translation>
        </message>
        <message>
            <source>Radius</source>
            <translation>半径</translation>
        </message>
        <message>
            <source>Angular pitch (°)</source>
            <translation>角度间距 (°)</translation>
        </message>
        <message>
            <source>Count (grid: columns)</source>
            <translation>数量（网格：列数）</translation>
        </message>
        <message>
            <source>Rows</source>
            <translation>行数</translation>
        </message>
        <message>
            <source>Hole</source>
            <translation>孔</translation>
        </message>
        <message>
            <source>Thread (tapped)</source>
            <translation>螺纹（攻丝）</translation>
        </message>
        <message>
            <source>Diameter</source>
            <translation>直径</translation>
        </message>
        <message>
            <source>Depth (full diameter)</source>
            <translation>深度（全直径部分）</translation>
        </message>
        <message>
            <source>How the holes are laid out: one hole, a line, a grid, a bolt circle or an arc</source>
            <translation>孔的排列方式：单孔、直线、网格、螺栓圆或圆弧</translation>
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
            <source>Bolt circle or arc: the radius the hole centres lie on</source>
            <translation>螺栓圆或圆弧:孔中心所在的半径</translation>
        </message>
        <message>
            <source>How many holes: along a line, around a circle or an arc; a grid's columns</source>
            <translation>孔数:沿直线、圆周或圆弧;网格为列数</translation>
        </message>
        <message>
            <source>Grid: how many rows of holes</source>
            <translation>网格:孔的行数</translation>
        </message>
        <message>
            <source>Tapped holes: the ISO metric coarse thread, M3 to M20</source>
            <translation>螺纹孔:ISO 公制粗牙螺纹 M3 至 M20</translation>
        </message>
        <message>
            <source>Diameter of a drilled, reamed or bored hole (a tapped hole takes its thread's)</source>
            <translation>钻孔、铰孔或镗孔的直径(螺纹孔取螺纹的直径)</translation>
        </message>
        <message>
            <source>Direction of a line's or grid's rows; angle of a circle's first hole</source>
            <translation>直线或网格各行的方向；圆上第一个孔的角度</translation>
        </message>
        <message>
            <source>Grid: distance between rows</source>
            <translation>网格：行与行的间距</translation>
        </message>
        <message>
            <source>Distance between neighbouring holes along the row</source>
            <translation>沿行相邻孔之间的距离</translation>
        </message>
        <message>
            <source>Arc: angle between neighbouring holes</source>
            <translation>圆弧：相邻孔之间的角度</translation>
        </message>
        <message>
            <source>Drilled, tapped, reamed or bored: which steps each hole gets</source>
            <translation>钻孔、攻丝、铰孔或镗孔：每个孔的加工工步</translation>
        </message>
        <message>
            <source>Depth of the full diameter (of the full thread), down from the top; the drill point goes deeper</source>
            <translation>全直径（完整螺纹）部分的深度，从顶面向下；钻尖会更深</translation>
        </message>
        <message>
            <source>L1 (length X)</source>
            <translation>L1(X 向长度)</translation>
        </message>
        <message>
            <source>L2 (length Y)</source>
            <translation>L2(Y 向长度)</translation>
        </message>
        <message>
            <source>θ1 (left wall, °)</source>
            <translation>θ1(左壁,°)</translation>
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
            <source>r1 (corner radius)</source>
            <translation>r1(拐角半径)</translation>
        </message>
        <message>
            <source>H (pilot hole)</source>
            <translation>H(预钻孔)</translation>
        </message>
        <message>
            <source>Scallop height</source>
            <translation>残留高度</translation>
        </message>
        <message>
            <source>The corner where the opening starts, at the top surface, in work coordinates</source>
            <translation>开口起始的角点，位于上表面，工件坐标</translation>
        </message>
        <message>
            <source>Length of the opening along X, at the top surface</source>
            <translation>开口沿 X 的长度（上表面）</translation>
        </message>
        <message>
            <source>Width of the opening along Y, at the top surface</source>
            <translation>开口沿 Y 的宽度（上表面）</translation>
        </message>
        <message>
            <source>Slope of the wall at the start of L1, in degrees from the vertical</source>
            <translation>L1 起始端侧壁的倾角（相对竖直方向，度）</translation>
        </message>
        <message>
            <source>Slope of the wall at the end of L1, in degrees from the vertical; empty for the same as θ1</source>
            <translation>L1 末端侧壁的倾角（相对竖直方向，度）；空表示与 θ1 相同</translation>
        </message>
        <message>
            <source>Radius of the pocket's corners; the finishing end mill must fit in it</source>
            <translation>型腔拐角半径；精加工立铣刀必须能放入</translation>
        </message>
        <message>
            <source>Whether a hole is drilled first for the roughing end mill to go down into</source>
            <translation>是否先钻孔，供粗加工立铣刀下刀</translation>
        </message>
        <message>
            <source>Largest ridge the ball end mill may leave between its passes on the inclined walls</source>
            <translation>球头铣刀在斜壁上两道刀路之间允许留下的最大残留高度</translation>
        </message>
        <message>
            <source>S (taper, °/side)</source>
            <translation>S(斜度,单边 °)</translation>
        </message>
        <message>
            <source>A corner of the pocket at the top surface, in work coordinates</source>
            <translation>型腔在上表面的角点（工件坐标）</translation>
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
            <source>Touched from</source>
            <translation>接触方向</translation>
        </message>
        <message>
            <source>P1 machine X</source>
            <translation>P1 机床坐标 X</translation>
        </message>
        <message>
            <source>P1 machine Y</source>
            <translation>P1 机床坐标 Y</translation>
        </message>
        <message>
            <source>Top face machine Z</source>
            <translation>顶面 机床坐标 Z</translation>
        </message>
        <message>
            <source>Tolerance</source>
            <translation>公差</translation>
        </message>
        <message>
            <source>Nominal diameter / width X</source>
            <translation>公称直径 / X 向宽度</translation>
        </message>
        <message>
            <source>Nominal length Y</source>
            <translation>公称长度 Y</translation>
        </message>
        <message>
            <source>Touch depth</source>
            <translation>接触深度</translation>
        </message>
        <message>
            <source>Clearance</source>
            <translation>安全距离</translation>
        </message>
        <message>
            <source>Search distance</source>
            <translation>搜索距离</translation>
        </message>
        <message>
            <source>Probing feed (mm/min)</source>
            <translation>测量进给 (mm/min)</translation>
        </message>
        <message>
            <source>Round (a boss or a bore) or rectangular (a block or a pocket)</source>
            <translation>圆形（凸台或孔）或矩形（块或型腔）</translation>
        </message>
        <message>
            <source>Whether the probe touches the part from outside or from inside</source>
            <translation>测头从外侧还是内侧接触工件</translation>
        </message>
        <message>
            <source>Where the first touch is, in machine coordinates</source>
            <translation>第一个测量点的位置（机床坐标）</translation>
        </message>
        <message>
            <source>A touch, relative to the first one; empty until it is measured</source>
            <translation>相对第一个点的测量点；测量前为空</translation>
        </message>
        <message>
            <source>Height of a touch on the top face, in machine coordinates; empty if not touched</source>
            <translation>顶面测量点的高度（机床坐标）；不测量则为空</translation>
        </message>
        <message>
            <source>Largest distance a touch may lie from the fitted shape</source>
            <translation>测量点离拟合形状允许的最大距离</translation>
        </message>
        <message>
            <source>Diameter of the round part, or its width along X</source>
            <translation>圆形工件的直径，或沿 X 的宽度</translation>
        </message>
        <message>
            <source>Length of the rectangular part along Y</source>
            <translation>矩形工件沿 Y 的长度</translation>
        </message>
        <message>
            <source>How far below the top face the probe touches the sides</source>
            <translation>测量侧面时距顶面的深度</translation>
        </message>
        <message>
            <source>Distance kept from the part while the probe moves between touches</source>
            <translation>测量点之间移动时与工件保持的距离</translation>
        </message>
        <message>
            <source>How far past the expected surface the probe looks for it before giving up</source>
            <translation>越过预期表面继续寻找的距离，找不到则停止</translation>
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
            <source>Tool side</source>
            <translation>刀具侧</translation>
        </message>
        <message>
            <source>Direction</source>
            <translation>方向</translation>
        </message>
        <message>
            <source>W (width)</source>
            <translation>W（宽度）</translation>
        </message>
        <message>
            <source>The contour of the figure that is the finished wall, open or closed (e.g. K1)</source>
            <translation>作为完成壁面的图形轮廓，可开放或闭合（例如 K1）</translation>
        </message>
        <message>
            <source>Which side of the contour, looking along its direction, the tool and the material to remove are on</source>
            <translation>沿轮廓方向看，刀具和待去除材料位于哪一侧</translation>
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
            <source>Profile</source>
            <translation>轮廓</translation>
        </message>
        <message>
            <source>Start X (diameter)</source>
            <translation>起点 X (直径)</translation>
        </message>
        <message>
            <source>Start Z</source>
            <translation>起点 Z</translation>
        </message>
        <message>
            <source>Outer profile (the outside diameter) or inner profile (a bore)</source>
            <translation>外轮廓（外径）或内轮廓（孔）</translation>
        </message>
        <message>
            <source>Diameter where the profile starts, at its front end</source>
            <translation>轮廓起点的直径（前端）</translation>
        </message>
        <message>
            <source>Z where the profile starts; 0 is the finished front face</source>
            <translation>轮廓起点的 Z；0 为精加工后的前端面</translation>
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
            <source>Add turned profile</source>
            <translation>添加车削轮廓</translation>
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
</TS>
