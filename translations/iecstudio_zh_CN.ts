<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
    <context>
        <name>GlobalListCommands</name>
        <message>
            <source>The configuration or resource for the list does not exist any more.</source>
            <translation>该列表所属的配置或资源已不存在。</translation>
        </message>
        <message>
            <source>Add global variable list %1</source>
            <translation>添加全局变量列表 %1</translation>
        </message>
        <message>
            <source>The list does not exist any more.</source>
            <translation>该列表已不存在。</translation>
        </message>
        <message>
            <source>Rename global variable list %1 to %2</source>
            <translation>将全局变量列表 %1 重命名为 %2</translation>
        </message>
        <message>
            <source>Duplicate global variable list %1</source>
            <translation>复制全局变量列表 %1</translation>
        </message>
        <message>
            <source>Delete global variable list %1</source>
            <translation>删除全局变量列表 %1</translation>
        </message>
        <message>
            <source>Create task configuration %1</source>
            <translation>创建任务配置 %1</translation>
        </message>
    </context>
    <context>
        <name>ImportExport</name>
        <message>
            <source>%1 is not a PLCopen XML project.</source>
            <translation>%1 不是 PLCopen XML 项目。</translation>
        </message>
        <message>
            <source>%1 cannot be read: %2</source>
            <translation>无法读取 %1：%2</translation>
        </message>
        <message>
            <source>%1 exists already; the imported one is named %2.</source>
            <translation>%1 已存在；导入的对象命名为 %2。</translation>
        </message>
        <message numerus="yes">
            <source>Import %n object(s)</source>
            <translation>
                <numerusform>导入 %n 个对象</numerusform>
            </translation>
        </message>
        <message>
            <source>The imported configuration %1 joins the project's configuration %2.</source>
            <translation>导入的配置 %1 已并入项目的配置 %2。</translation>
        </message>
        <message>
            <source>%1 exists already in resource %2; the imported one is named %3.</source>
            <translation>资源 %2 中已有 %1；导入的对象命名为 %3。</translation>
        </message>
    </context>
    <context>
        <name>ModelCompletionProvider</name>
        <message>
            <source>Global variables</source>
            <translation>全局变量</translation>
        </message>
        <message>
            <source>Local variables</source>
            <translation>局部变量</translation>
        </message>
        <message>
            <source>Programs</source>
            <translation>程序</translation>
        </message>
        <message>
            <source>Function blocks</source>
            <translation>功能块</translation>
        </message>
        <message>
            <source>Functions</source>
            <translation>函数</translation>
        </message>
    </context>
    <context>
        <name>NameRules</name>
        <message>
            <source>Enter a name.</source>
            <translation>请输入名称。</translation>
        </message>
        <message>
            <source>"%1" is not an IEC identifier: use letters, digits and single underscores, starting with a letter or an underscore and not ending with an underscore.</source>
            <translation>"%1" 不是 IEC 标识符：只能使用字母、数字和单个下划线，以字母或下划线开头，且不能以下划线结尾。</translation>
        </message>
        <message>
            <source>"%1" is a reserved word of IEC 61131-3.</source>
            <translation>"%1" 是 IEC 61131-3 的保留字。</translation>
        </message>
        <message>
            <source>A POU or data type named "%1" exists already.</source>
            <translation>名为 "%1" 的 POU 或数据类型已存在。</translation>
        </message>
        <message>
            <source>This POU has an action or transition named "%1" already.</source>
            <translation>此 POU 已有名为 "%1" 的动作或转换。</translation>
        </message>
        <message>
            <source>A global variable list named "%1" exists already.</source>
            <translation>名为 "%1" 的全局变量列表已存在。</translation>
        </message>
        <message>
            <source>This function block has a method or property named "%1" already.</source>
            <translation>该功能块已有名为“%1”的方法或属性。</translation>
        </message>
        <message>
            <source>An interface named "%1" exists already.</source>
            <translation>名为“%1”的接口已存在。</translation>
        </message>
    </context>
    <context>
        <name>ProjectCommands</name>
        <message>
            <source>A function needs a return type.</source>
            <translation>函数需要返回类型。</translation>
        </message>
        <message>
            <source>The POU does not exist any more.</source>
            <translation>该程序组织单元已不存在。</translation>
        </message>
        <message>
            <source>The item does not exist any more.</source>
            <translation>该项已不存在。</translation>
        </message>
        <message>
            <source>Methods and properties belong to function blocks.</source>
            <translation>方法和属性只能属于功能块。</translation>
        </message>
        <message>
            <source>The name "%1" cannot start a method.</source>
            <translation>无法用名称“%1”创建方法。</translation>
        </message>
        <message>
            <source>Add Property %1</source>
            <translation>添加属性 %1</translation>
        </message>
        <message>
            <source>Add Method %1</source>
            <translation>添加方法 %1</translation>
        </message>
        <message>
            <source>Delete %1</source>
            <translation>删除 %1</translation>
        </message>
        <message>
            <source>Add Interface %1</source>
            <translation>添加接口 %1</translation>
        </message>
    </context>
    <context>
        <name>ProjectTemplates</name>
        <message>
            <source>Closes the contact</source>
            <translation>闭合触点</translation>
        </message>
        <message>
            <source>Lit while Start is TRUE</source>
            <translation>Start 为 TRUE 时点亮</translation>
        </message>
        <message>
            <source>Switches Lamp on and off</source>
            <translation>控制 Lamp 的开关</translation>
        </message>
    </context>
    <context>
        <name>iec::app</name>
        <message>
            <source>Rename variable %1 to %2</source>
            <translation>将变量 %1 重命名为 %2</translation>
        </message>
        <message>
            <source>Rename global variable %1 to %2</source>
            <translation>将全局变量 %1 重命名为 %2</translation>
        </message>
        <message>
            <source>Rename member %1 to %2</source>
            <translation>将成员 %1 重命名为 %2</translation>
        </message>
    </context>
    <context>
        <name>iec::app::AddPouDialog</name>
        <message>
            <source>Add POU</source>
            <translation>添加 POU</translation>
        </message>
        <message>
            <source>Program</source>
            <translation>程序</translation>
        </message>
        <message>
            <source>Function Block</source>
            <translation>功能块</translation>
        </message>
        <message>
            <source>Function</source>
            <translation>函数</translation>
        </message>
        <message>
            <source>&amp;Name:</source>
            <translation>名称(&amp;N)：</translation>
        </message>
        <message>
            <source>&amp;Kind:</source>
            <translation>类型(&amp;K)：</translation>
        </message>
        <message>
            <source>&amp;Language:</source>
            <translation>语言(&amp;L)：</translation>
        </message>
        <message>
            <source>&amp;Return type:</source>
            <translation>返回类型(&amp;R)：</translation>
        </message>
        <message>
            <source>A function needs a return type.</source>
            <translation>函数需要返回类型。</translation>
        </message>
    </context>
    <context>
        <name>iec::app::AddPouPartDialog</name>
        <message>
            <source>Add Action</source>
            <translation>添加动作</translation>
        </message>
        <message>
            <source>Add Transition</source>
            <translation>添加转换</translation>
        </message>
        <message>
            <source>&amp;Name:</source>
            <translation>名称(&amp;N)：</translation>
        </message>
        <message>
            <source>&amp;Language:</source>
            <translation>语言(&amp;L)：</translation>
        </message>
    </context>
    <context>
        <name>iec::app::AutoDeclare</name>
        <message>
            <source>The POU does not exist any more.</source>
            <translation>该程序组织单元已不存在。</translation>
        </message>
        <message>
            <source>Declare %1</source>
            <translation>声明 %1</translation>
        </message>
    </context>
    <context>
        <name>iec::app::AutoDeclareDialog</name>
        <message>
            <source>Declare Variable</source>
            <translation>声明变量</translation>
        </message>
        <message>
            <source>&amp;Name:</source>
            <translation>名称(&amp;N)：</translation>
        </message>
        <message>
            <source>&amp;Class:</source>
            <translation>类别(&amp;C)：</translation>
        </message>
        <message>
            <source>&amp;Type:</source>
            <translation>类型(&amp;T)：</translation>
        </message>
        <message>
            <source>&amp;Initial value:</source>
            <translation>初始值(&amp;I)：</translation>
        </message>
        <message>
            <source>C&amp;omment:</source>
            <translation>注释(&amp;O)：</translation>
        </message>
    </context>
    <context>
        <name>iec::app::BreakpointDialog</name>
        <message>
            <source>Enabled</source>
            <translation>启用</translation>
        </message>
        <message>
            <source>Breakpoint Properties</source>
            <translation>断点属性</translation>
        </message>
        <message>
            <source>Break always</source>
            <translation>总是暂停</translation>
        </message>
        <message>
            <source>Break when the hit count is equal to</source>
            <translation>命中次数等于时暂停</translation>
        </message>
        <message>
            <source>Break when the hit count is a multiple of</source>
            <translation>命中次数为下值的倍数时暂停</translation>
        </message>
        <message>
            <source>Break when the hit count is greater than or equal to</source>
            <translation>命中次数大于或等于时暂停</translation>
        </message>
        <message>
            <source>for example  Count = 5 AND NOT Alarm</source>
            <translation>例如  Count = 5 AND NOT Alarm</translation>
        </message>
        <message>
            <source>Place:</source>
            <translation>位置：</translation>
        </message>
        <message>
            <source>Hit count:</source>
            <translation>命中次数：</translation>
        </message>
        <message>
            <source>Break when TRUE:</source>
            <translation>为 TRUE 时暂停：</translation>
        </message>
    </context>
    <context>
        <name>iec::app::BuildController</name>
        <message>
            <source>%1 Hint: %2</source>
            <translation>%1 提示：%2</translation>
        </message>
    </context>
    <context>
        <name>iec::app::DebugController</name>
        <message>
            <source>Toggle &amp;Breakpoint</source>
            <translation>切换断点(&amp;B)</translation>
        </message>
        <message>
            <source>Remove All Breakpoints</source>
            <translation>删除所有断点</translation>
        </message>
        <message>
            <source>Step &amp;Over</source>
            <translation>单步跳过(&amp;O)</translation>
        </message>
        <message>
            <source>Step &amp;Into</source>
            <translation>单步进入(&amp;I)</translation>
        </message>
        <message>
            <source>Step O&amp;ut</source>
            <translation>单步跳出(&amp;U)</translation>
        </message>
        <message>
            <source>Breakpoints in transitions are not supported; put one on the step before it.</source>
            <translation>转换中不支持断点；请把断点设在它前面的步上。</translation>
        </message>
        <message>
            <source>element %1</source>
            <translation>元素 %1</translation>
        </message>
        <message>
            <source>line %1</source>
            <translation>第 %1 行</translation>
        </message>
        <message>
            <source>Halted in %1 at %2 (cycle %3). F5 continues, F10 steps over, F8 steps into, Shift+F10 steps out.</source>
            <translation>已在 %1 的%2处暂停（周期 %3）。F5 继续，F10 单步跳过，F8 单步进入，Shift+F10 单步跳出。</translation>
        </message>
        <message>
            <source>The breakpoint's condition could not be checked: %1</source>
            <translation>无法检查断点的条件：%1</translation>
        </message>
        <message>
            <source>Breakpoint &amp;Properties...</source>
            <translation>断点属性(&amp;P)...</translation>
        </message>
        <message>
            <source>%1, element %2</source>
            <translation>%1，元素 %2</translation>
        </message>
        <message>
            <source>%1, line %2</source>
            <translation>%1，第 %2 行</translation>
        </message>
        <message>
            <source>A breakpoint goes on a line of an ST or IL body, a network of an LD or FBD body, or a step or transition of a chart: put the cursor there first.</source>
            <translation>断点可设在 ST 或 IL 程序体的一行、LD 或 FBD 程序体的一个网络，或顺序功能图的一个步或转换上：请先把光标放到那里。</translation>
        </message>
        <message>
            <source>Run to &amp;Cursor</source>
            <translation>运行到光标处(&amp;C)</translation>
        </message>
        <message>
            <source>%1 (instance %2)</source>
            <translation>%1（实例 %2）</translation>
        </message>
        <message>
            <source>Halted in %1 at %2 (cycle %3).</source>
            <translation>已在 %1 的%2处暂停（周期 %3）。</translation>
        </message>
        <message>
            <source>Called from %1 at %2.</source>
            <translation>由 %1 的%2处调用。</translation>
        </message>
    </context>
    <context>
        <name>iec::app::DiagramMenus</name>
        <message>
            <source>Zoom: %1 %</source>
            <translation>缩放：%1 %</translation>
        </message>
    </context>
    <context>
        <name>iec::app::DocumentArea</name>
        <message>
            <source>This body is written in %1. Its editor is not available in this version; the body is kept unchanged when the project is saved.</source>
            <translation>此程序体使用 %1 编写。本版本尚未提供该语言的编辑器；保存项目时程序体保持不变。</translation>
        </message>
        <message>
            <source>Declare Variable...</source>
            <translation>声明变量...</translation>
        </message>
        <message>
            <source>%1 is declared already.</source>
            <translation>%1 已经声明。</translation>
        </message>
    </context>
    <context>
        <name>iec::app::EditActions</name>
        <message>
            <source>Cu&amp;t</source>
            <translation>剪切(&amp;T)</translation>
        </message>
        <message>
            <source>&amp;Copy</source>
            <translation>复制(&amp;C)</translation>
        </message>
        <message>
            <source>&amp;Paste</source>
            <translation>粘贴(&amp;P)</translation>
        </message>
        <message>
            <source>&amp;Delete</source>
            <translation>删除(&amp;D)</translation>
        </message>
        <message>
            <source>Select &amp;All</source>
            <translation>全选(&amp;A)</translation>
        </message>
        <message>
            <source>&amp;Find...</source>
            <translation>查找(&amp;F)...</translation>
        </message>
        <message>
            <source>R&amp;eplace...</source>
            <translation>替换(&amp;E)...</translation>
        </message>
    </context>
    <context>
        <name>iec::app::FindInProjectDialog</name>
        <message>
            <source>Match &amp;case</source>
            <translation>区分大小写(&amp;C)</translation>
        </message>
        <message>
            <source>&amp;Whole words</source>
            <translation>全字匹配(&amp;W)</translation>
        </message>
        <message>
            <source>&amp;Regular expression</source>
            <translation>正则表达式(&amp;R)</translation>
        </message>
        <message>
            <source>Find in Project</source>
            <translation>在项目中查找</translation>
        </message>
        <message>
            <source>Find:</source>
            <translation>查找：</translation>
        </message>
        <message>
            <source>Find</source>
            <translation>查找</translation>
        </message>
    </context>
    <context>
        <name>iec::app::HistoryBar</name>
        <message>
            <source>Scan History</source>
            <translation>扫描历史</translation>
        </message>
        <message>
            <source>History: </source>
            <translation>历史：</translation>
        </message>
        <message>
            <source>Present</source>
            <translation>当前</translation>
        </message>
        <message>
            <source>Show the program as it is now</source>
            <translation>显示程序的当前状态</translation>
        </message>
        <message>
            <source>Resume from Here</source>
            <translation>从此处继续</translation>
        </message>
        <message>
            <source>Go on from the scan shown: the scans after it are dropped, the next cycle starts from its values (write new inputs first, if you like)</source>
            <translation>从所显示的扫描继续：其后的扫描被丢弃，下一个周期从它的值开始（可以先写入新的输入）</translation>
        </message>
        <message>
            <source>Drag (or use the arrow keys) to see the program after an earlier scan</source>
            <translation>拖动（或用方向键）查看程序在较早扫描之后的状态</translation>
        </message>
        <message>
            <source>%1 / %2</source>
            <translation>%1 / %2</translation>
        </message>
        <message>
            <source>%1 of at most %2 scans kept, %3</source>
            <translation>已保存 %1 个扫描（最多 %2 个），%3</translation>
        </message>
        <message>
            <source>History: after scan %1 (the program is at %2)</source>
            <translation>历史：第 %1 次扫描之后（程序在第 %2 次）</translation>
        </message>
    </context>
    <context>
        <name>iec::app::ImportExportActions</name>
        <message>
            <source>&amp;Import...</source>
            <translation>导入(&amp;I)...</translation>
        </message>
        <message>
            <source>&amp;Export Project...</source>
            <translation>导出项目(&amp;E)...</translation>
        </message>
        <message>
            <source>Export Se&amp;lection...</source>
            <translation>导出所选(&amp;L)...</translation>
        </message>
        <message>
            <source>Imported %1: %2 POU(s), %3 data type(s).</source>
            <translation>已导入 %1：%2 个程序组织单元，%3 个数据类型。</translation>
        </message>
        <message>
            <source>Nothing could be read from %1.</source>
            <translation>无法从 %1 读取任何内容。</translation>
        </message>
        <message>
            <source>Import</source>
            <translation>导入</translation>
        </message>
        <message>
            <source>PLCopen XML (*.xml)</source>
            <translation>PLCopen XML (*.xml)</translation>
        </message>
        <message>
            <source>IEC 61131-3 text (*.st)</source>
            <translation>IEC 61131-3 文本 (*.st)</translation>
        </message>
        <message>
            <source>Export</source>
            <translation>导出</translation>
        </message>
        <message>
            <source>PLCopen XML or IEC text (*.xml *.st *.exp *.iec *.txt);;PLCopen XML (*.xml);;IEC 61131-3 text (*.st *.exp *.iec *.txt)</source>
            <translation>PLCopen XML 或 IEC 文本 (*.xml *.st *.exp *.iec *.txt);;PLCopen XML (*.xml);;IEC 61131-3 文本 (*.st *.exp *.iec *.txt)</translation>
        </message>
    </context>
    <context>
        <name>iec::app::LibraryPane</name>
        <message>
            <source>Standard library</source>
            <translation>标准库</translation>
        </message>
        <message>
            <source>%1 library</source>
            <translation>%1 库</translation>
        </message>
        <message>
            <source>Project</source>
            <translation>项目</translation>
        </message>
        <message>
            <source>Function Blocks</source>
            <translation>功能块</translation>
        </message>
        <message>
            <source>Functions</source>
            <translation>函数</translation>
        </message>
        <message>
            <source>A function block of this project.</source>
            <translation>本项目中的一个功能块。</translation>
        </message>
        <message>
            <source>A function of this project.</source>
            <translation>本项目中的一个函数。</translation>
        </message>
        <message>
            <source>(function block)</source>
            <translation>（功能块）</translation>
        </message>
        <message>
            <source>(function)</source>
            <translation>（函数）</translation>
        </message>
        <message>
            <source>Inputs:</source>
            <translation>输入：</translation>
        </message>
        <message>
            <source>Outputs:</source>
            <translation>输出：</translation>
        </message>
        <message>
            <source>Returns:</source>
            <translation>返回值：</translation>
        </message>
        <message>
            <source>Search blocks</source>
            <translation>搜索功能块</translation>
        </message>
        <message>
            <source>Choose a block to see its pins; drag it into an editor to call it.</source>
            <translation>选择一个块可查看其引脚；将其拖入编辑器即可调用。</translation>
        </message>
    </context>
    <context>
        <name>iec::app::MainWindow</name>
        <message>
            <source>&amp;File</source>
            <translation>文件(&amp;F)</translation>
        </message>
        <message>
            <source>&amp;Edit</source>
            <translation>编辑(&amp;E)</translation>
        </message>
        <message>
            <source>&amp;View</source>
            <translation>视图(&amp;V)</translation>
        </message>
        <message>
            <source>&amp;Project</source>
            <translation>项目(&amp;P)</translation>
        </message>
        <message>
            <source>&amp;Online</source>
            <translation>在线(&amp;O)</translation>
        </message>
        <message>
            <source>&amp;Help</source>
            <translation>帮助(&amp;H)</translation>
        </message>
        <message>
            <source>&amp;Quit</source>
            <translation>退出(&amp;Q)</translation>
        </message>
        <message>
            <source>&amp;Build</source>
            <translation>编译(&amp;B)</translation>
        </message>
        <message>
            <source>Login and &amp;Run</source>
            <translation>登录并运行(&amp;R)</translation>
        </message>
        <message>
            <source>&amp;Stop</source>
            <translation>停止(&amp;S)</translation>
        </message>
        <message>
            <source>Single &amp;Cycle</source>
            <translation>单周期(&amp;C)</translation>
        </message>
        <message>
            <source>&amp;About IEC Studio</source>
            <translation>关于 IEC Studio(&amp;A)</translation>
        </message>
        <message>
            <source>About &amp;Qt</source>
            <translation>关于 &amp;Qt</translation>
        </message>
        <message>
            <source>Project</source>
            <translation>项目</translation>
        </message>
        <message>
            <source>Messages</source>
            <translation>消息</translation>
        </message>
        <message>
            <source>About IEC Studio</source>
            <translation>关于 IEC Studio</translation>
        </message>
        <message>
            <source>&lt;h3&gt;IEC Studio %1&lt;/h3&gt;&lt;p&gt;An IDE for the five IEC 61131-3 languages: Ladder Diagram, Function Block Diagram with CFC, Sequential Function Chart, Instruction List and Structured Text.&lt;/p&gt;&lt;p&gt;Projects are stored as PLCopen TC6 XML v2.01.&lt;/p&gt;</source>
            <translation>&lt;h3&gt;IEC Studio %1&lt;/h3&gt;&lt;p&gt;面向 IEC 61131-3 五种编程语言的集成开发环境：梯形图、功能块图(含 CFC)、顺序功能图、指令表和结构化文本。&lt;/p&gt;&lt;p&gt;项目以 PLCopen TC6 XML v2.01 格式保存。&lt;/p&gt;</translation>
        </message>
        <message>
            <source>&amp;Settings...</source>
            <translation>设置(&amp;S)...</translation>
        </message>
        <message>
            <source>&amp;New Project</source>
            <translation>新建项目(&amp;N)</translation>
        </message>
        <message>
            <source>&amp;Open...</source>
            <translation>打开(&amp;O)...</translation>
        </message>
        <message>
            <source>&amp;Save</source>
            <translation>保存(&amp;S)</translation>
        </message>
        <message>
            <source>Save &amp;As...</source>
            <translation>另存为(&amp;A)...</translation>
        </message>
        <message>
            <source>Untitled</source>
            <translation>未命名</translation>
        </message>
        <message>
            <source>%1[*] - IEC Studio</source>
            <translation>%1[*] - IEC Studio</translation>
        </message>
        <message>
            <source>%1 is not a PLCopen XML project.</source>
            <translation>%1 不是 PLCopen XML 项目。</translation>
        </message>
        <message>
            <source>Unsaved Changes</source>
            <translation>未保存的更改</translation>
        </message>
        <message>
            <source>The project has unsaved changes. Save them first?</source>
            <translation>项目有未保存的更改。是否先保存？</translation>
        </message>
        <message>
            <source>Open Project</source>
            <translation>打开项目</translation>
        </message>
        <message>
            <source>The project could not be opened: %1</source>
            <translation>无法打开项目：%1</translation>
        </message>
        <message>
            <source>Save Project</source>
            <translation>保存项目</translation>
        </message>
        <message>
            <source>The project could not be saved: %1</source>
            <translation>无法保存项目：%1</translation>
        </message>
        <message>
            <source>Save Project As</source>
            <translation>项目另存为</translation>
        </message>
        <message>
            <source>PLCopen XML projects (*.xml)</source>
            <translation>PLCopen XML 项目 (*.xml)</translation>
        </message>
        <message>
            <source>&amp;Insert</source>
            <translation>插入(&amp;I)</translation>
        </message>
        <message>
            <source>&amp;Window</source>
            <translation>窗口(&amp;W)</translation>
        </message>
        <message>
            <source>Recent &amp;Projects</source>
            <translation>最近的项目(&amp;P)</translation>
        </message>
        <message>
            <source>&amp;Examples</source>
            <translation>示例(&amp;E)</translation>
        </message>
        <message>
            <source>Toolbar</source>
            <translation>工具栏</translation>
        </message>
        <message>
            <source>%1 (%2)</source>
            <translation>%1 (%2)</translation>
        </message>
        <message>
            <source>Autosave failed: %1</source>
            <translation>自动保存失败：%1</translation>
        </message>
        <message>
            <source>%1 does not exist any more; it was removed from the recent projects.</source>
            <translation>%1 已不存在，已从最近的项目中移除。</translation>
        </message>
        <message>
            <source>(untitled)</source>
            <translation>(未命名)</translation>
        </message>
        <message>
            <source>Recover Project</source>
            <translation>恢复项目</translation>
        </message>
        <message>
            <source>IEC Studio did not close properly. Recover the autosaved changes?</source>
            <translation>IEC Studio 未正常关闭。是否恢复自动保存的更改？</translation>
        </message>
        <message>
            <source>Project: %1
Autosaved: %2</source>
            <translation>项目：%1
自动保存于：%2</translation>
        </message>
        <message>
            <source>&amp;Recover</source>
            <translation>恢复(&amp;R)</translation>
        </message>
        <message>
            <source>Ask &amp;Later</source>
            <translation>稍后询问(&amp;L)</translation>
        </message>
        <message>
            <source>The project could not be recovered: %1</source>
            <translation>无法恢复项目：%1</translation>
        </message>
        <message>
            <source>Build finished. Errors: %1, warnings: %2.</source>
            <translation>编译完成。错误：%1，警告：%2。</translation>
        </message>
        <message>
            <source>Watch</source>
            <translation>监视</translation>
        </message>
        <message>
            <source>Log out to edit (Online → Logout).</source>
            <translation>要编辑，请先注销（在线 → 注销）。</translation>
        </message>
        <message>
            <source>Search Results</source>
            <translation>搜索结果</translation>
        </message>
        <message>
            <source>Library</source>
            <translation>库</translation>
        </message>
        <message>
            <source>&amp;Print Documentation...</source>
            <translation>打印文档(&amp;P)...</translation>
        </message>
        <message>
            <source>Export Documentation as P&amp;DF...</source>
            <translation>将文档导出为 PDF(&amp;D)...</translation>
        </message>
        <message>
            <source>Print Documentation</source>
            <translation>打印文档</translation>
        </message>
        <message>
            <source>Export Documentation</source>
            <translation>导出文档</translation>
        </message>
        <message>
            <source>PDF documents (*.pdf)</source>
            <translation>PDF 文档 (*.pdf)</translation>
        </message>
        <message>
            <source>The documentation was written to %1.</source>
            <translation>文档已写入 %1。</translation>
        </message>
        <message>
            <source>Trace: %1</source>
            <translation>跟踪：%1</translation>
        </message>
        <message>
            <source>Trace</source>
            <translation>跟踪</translation>
        </message>
        <message>
            <source>%1, line %2: %3</source>
            <translation>%1，第 %2 行：%3</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1：%2</translation>
        </message>
        <message>
            <source>PLCopen XML projects (*.xml);;IEC 61131-3 text (*.st *.exp *.iec *.txt);;All files (*)</source>
            <translation>PLCopen XML 项目 (*.xml);;IEC 61131-3 文本 (*.st *.exp *.iec *.txt);;所有文件 (*)</translation>
        </message>
    </context>
    <context>
        <name>iec::app::MemberEditor</name>
        <message>
            <source>%1 already has a method or property called %2.</source>
            <translation>%1 已有名为 %2 的方法或属性。</translation>
        </message>
    </context>
    <context>
        <name>iec::app::MessagesPane</name>
        <message>
            <source>%1, line %2, column %3</source>
            <translation>%1，第 %2 行，第 %3 列</translation>
        </message>
        <message>
            <source>%1, line %2</source>
            <translation>%1，第 %2 行</translation>
        </message>
        <message>
            <source>%1, element %2</source>
            <translation>%1，元素 %2</translation>
        </message>
        <message>
            <source>Info</source>
            <translation>信息</translation>
        </message>
        <message>
            <source>Warning</source>
            <translation>警告</translation>
        </message>
        <message>
            <source>Error</source>
            <translation>错误</translation>
        </message>
        <message>
            <source>Severity</source>
            <translation>级别</translation>
        </message>
        <message>
            <source>Description</source>
            <translation>描述</translation>
        </message>
        <message>
            <source>Location</source>
            <translation>位置</translation>
        </message>
        <message>
            <source>Errors: %1, warnings: %2</source>
            <translation>错误：%1，警告：%2</translation>
        </message>
        <message>
            <source>%1, element %2, column %3</source>
            <translation>%1，元素 %2，第 %3 列</translation>
        </message>
    </context>
    <context>
        <name>iec::app::NewProjectDialog</name>
        <message>
            <source>New Project</source>
            <translation>新建项目</translation>
        </message>
        <message>
            <source>Start the project from:</source>
            <translation>项目起点：</translation>
        </message>
    </context>
    <context>
        <name>iec::app::OnlineController</name>
        <message>
            <source>Log&amp;out</source>
            <translation>注销(&amp;O)</translation>
        </message>
        <message>
            <source>Run &amp;N Cycles...</source>
            <translation>运行 N 个周期(&amp;N)...</translation>
        </message>
        <message>
            <source>Reset &amp;Warm</source>
            <translation>热复位(&amp;W)</translation>
        </message>
        <message>
            <source>Reset C&amp;old</source>
            <translation>冷复位(&amp;O)</translation>
        </message>
        <message>
            <source>C&amp;ycle Time</source>
            <translation>周期时间(&amp;Y)</translation>
        </message>
        <message>
            <source>S&amp;peed</source>
            <translation>速度(&amp;P)</translation>
        </message>
        <message>
            <source>%1 ms</source>
            <translation>%1 ms</translation>
        </message>
        <message>
            <source>&amp;Real Time</source>
            <translation>实时(&amp;R)</translation>
        </message>
        <message>
            <source>&amp;10 Times Faster</source>
            <translation>快 10 倍(&amp;1)</translation>
        </message>
        <message>
            <source>As &amp;Fast as Possible</source>
            <translation>尽可能快(&amp;F)</translation>
        </message>
        <message>
            <source>The cycle time takes effect at login and at a reset.</source>
            <translation>周期时间在登录和复位时生效。</translation>
        </message>
        <message>
            <source>Login refused: the project has errors. See the Messages pane.</source>
            <translation>拒绝登录:项目有错误。请查看消息窗口。</translation>
        </message>
        <message>
            <source>Logged out.</source>
            <translation>已注销。</translation>
        </message>
        <message>
            <source>Run N Cycles</source>
            <translation>运行 N 个周期</translation>
        </message>
        <message>
            <source>Number of cycles:</source>
            <translation>周期数:</translation>
        </message>
        <message>
            <source>Log in to write values.</source>
            <translation>请先登录再写入值。</translation>
        </message>
        <message>
            <source>Log in to force values.</source>
            <translation>请先登录再强制值。</translation>
        </message>
        <message>
            <source>The new cycle time takes effect at the next reset.</source>
            <translation>新的周期时间在下次复位时生效。</translation>
        </message>
        <message>
            <source>Runtime fault in cycle %1: %2 The program stopped; Reset starts it again.</source>
            <translation>第 %1 周期运行时故障:%2 程序已停止;复位后可重新启动。</translation>
        </message>
        <message>
            <source>The program stopped: %1</source>
            <translation>程序已停止:%1</translation>
        </message>
        <message>
            <source>Offline</source>
            <translation>离线</translation>
        </message>
        <message>
            <source>real time</source>
            <translation>实时</translation>
        </message>
        <message>
            <source>10x</source>
            <translation>10 倍</translation>
        </message>
        <message>
            <source>full speed</source>
            <translation>全速</translation>
        </message>
        <message>
            <source>FAULT</source>
            <translation>故障</translation>
        </message>
        <message>
            <source>RUN</source>
            <translation>运行</translation>
        </message>
        <message>
            <source>STOP</source>
            <translation>停止</translation>
        </message>
        <message>
            <source>ONLINE %1 | cycle %2 | t = %3 s | %4 ms, %5</source>
            <translation>在线 %1 | 周期 %2 | t = %3 s | %4 ms, %5</translation>
        </message>
        <message>
            <source> | changed since login</source>
            <translation> | 登录后已更改</translation>
        </message>
        <message>
            <source>Logged in. F5 runs the program, Ctrl+F5 runs one cycle. Log out to edit (Online → Logout).</source>
            <translation>已登录。F5 运行程序，Ctrl+F5 运行一个周期。要编辑，请先注销（在线 → 注销）。</translation>
        </message>
        <message>
            <source>HALT</source>
            <translation>暂停</translation>
        </message>
        <message>
            <source>ONLINE HISTORY | scan %1 of %2 | t = %3 s</source>
            <translation>在线 历史 | 扫描 %1 / %2 | t = %3 s</translation>
        </message>
        <message>
            <source>Program log: %1</source>
            <translation>程序日志：%1</translation>
        </message>
    </context>
    <context>
        <name>iec::app::ProjectDocumentation</name>
        <message>
            <source>program</source>
            <translation>程序</translation>
        </message>
        <message>
            <source>function block</source>
            <translation>功能块</translation>
        </message>
        <message>
            <source>function</source>
            <translation>函数</translation>
        </message>
        <message>
            <source>The body is empty.</source>
            <translation>程序体为空。</translation>
        </message>
        <message>
            <source>The %1 body is drawn in the editor; this version cannot print it as a picture.</source>
            <translation>%1 程序体在编辑器中以图形绘制；此版本无法将其打印为图片。</translation>
        </message>
        <message>
            <source>%1 (%2, %3)</source>
            <translation>%1（%2，%3）</translation>
        </message>
        <message>
            <source>Declarations</source>
            <translation>声明</translation>
        </message>
        <message>
            <source>Returns %1.</source>
            <translation>返回 %1。</translation>
        </message>
        <message>
            <source>No variables.</source>
            <translation>无变量。</translation>
        </message>
        <message>
            <source>Body</source>
            <translation>程序体</translation>
        </message>
        <message>
            <source>Action %1</source>
            <translation>动作 %1</translation>
        </message>
        <message>
            <source>Transition %1</source>
            <translation>转换 %1</translation>
        </message>
        <message>
            <source>Data types</source>
            <translation>数据类型</translation>
        </message>
        <message>
            <source>Global variables</source>
            <translation>全局变量</translation>
        </message>
        <message>
            <source>%1 (in %2)</source>
            <translation>%1（位于 %2）</translation>
        </message>
        <message>
            <source>Configuration %1</source>
            <translation>配置 %1</translation>
        </message>
        <message>
            <source>Resource %1</source>
            <translation>资源 %1</translation>
        </message>
        <message>
            <source>No tasks.</source>
            <translation>无任务。</translation>
        </message>
        <message>
            <source>Task</source>
            <translation>任务</translation>
        </message>
        <message>
            <source>Interval</source>
            <translation>间隔</translation>
        </message>
        <message>
            <source>SINGLE</source>
            <translation>SINGLE</translation>
        </message>
        <message>
            <source>Priority</source>
            <translation>优先级</translation>
        </message>
        <message>
            <source>Watchdog</source>
            <translation>看门狗</translation>
        </message>
        <message>
            <source>Programs</source>
            <translation>程序</translation>
        </message>
        <message>
            <source>Untitled project</source>
            <translation>未命名项目</translation>
        </message>
        <message>
            <source>Project documentation</source>
            <translation>项目文档</translation>
        </message>
        <message>
            <source>Author: %1</source>
            <translation>作者：%1</translation>
        </message>
        <message>
            <source>Organization: %1</source>
            <translation>组织：%1</translation>
        </message>
        <message>
            <source>Version: %1</source>
            <translation>版本：%1</translation>
        </message>
        <message>
            <source>Printed on %1</source>
            <translation>打印于 %1</translation>
        </message>
        <message>
            <source>Contents</source>
            <translation>目录</translation>
        </message>
        <message>
            <source>The PDF could not be written to %1.</source>
            <translation>无法将 PDF 写入 %1。</translation>
        </message>
    </context>
    <context>
        <name>iec::app::ProjectSearch</name>
        <message>
            <source>The regular expression is not valid: %1.</source>
            <translation>正则表达式无效：%1。</translation>
        </message>
        <message>
            <source>declared</source>
            <translation>声明</translation>
        </message>
        <message>
            <source>read</source>
            <translation>读取</translation>
        </message>
        <message>
            <source>written</source>
            <translation>写入</translation>
        </message>
        <message>
            <source>read and written</source>
            <translation>读取和写入</translation>
        </message>
    </context>
    <context>
        <name>iec::app::ProjectTemplates</name>
        <message>
            <source>Empty project</source>
            <translation>空项目</translation>
        </message>
        <message>
            <source>Structured Text (ST) program</source>
            <translation>结构化文本 (ST) 程序</translation>
        </message>
        <message>
            <source>Ladder Diagram (LD) program</source>
            <translation>梯形图 (LD) 程序</translation>
        </message>
        <message>
            <source>Function Block Diagram (FBD) program</source>
            <translation>功能块图 (FBD) 程序</translation>
        </message>
        <message>
            <source>Continuous Function Chart (CFC) program</source>
            <translation>连续功能图 (CFC) 程序</translation>
        </message>
        <message>
            <source>Sequential Function Chart (SFC) program</source>
            <translation>顺序功能图 (SFC) 程序</translation>
        </message>
        <message>
            <source>Instruction List (IL) program</source>
            <translation>指令表 (IL) 程序</translation>
        </message>
        <message>
            <source>No POUs and no configuration: add what you need from the Project menu.</source>
            <translation>没有程序组织单元，也没有配置：请通过“项目”菜单添加所需内容。</translation>
        </message>
        <message>
            <source>A program Main, run every 10 ms by the task MainTask of configuration Config.</source>
            <translation>一个程序 Main，由配置 Config 中的任务 MainTask 每 10 ms 执行一次。</translation>
        </message>
    </context>
    <context>
        <name>iec::app::ProjectTreeActions</name>
        <message>
            <source>Add &amp;POU...</source>
            <translation>添加 POU(&amp;P)...</translation>
        </message>
        <message>
            <source>Add &amp;Action...</source>
            <translation>添加动作(&amp;A)...</translation>
        </message>
        <message>
            <source>Add &amp;Transition...</source>
            <translation>添加转换(&amp;T)...</translation>
        </message>
        <message>
            <source>&amp;Rename...</source>
            <translation>重命名(&amp;R)...</translation>
        </message>
        <message>
            <source>&amp;Delete</source>
            <translation>删除(&amp;D)</translation>
        </message>
        <message>
            <source>D&amp;uplicate</source>
            <translation>复制(&amp;U)</translation>
        </message>
        <message>
            <source>Add POU</source>
            <translation>添加 POU</translation>
        </message>
        <message>
            <source>Rename %1</source>
            <translation>重命名 %1</translation>
        </message>
        <message>
            <source>Delete</source>
            <translation>删除</translation>
        </message>
        <message>
            <source>Delete %1? Edit → Undo brings it back.</source>
            <translation>删除 %1？可通过 编辑 → 撤销 恢复。</translation>
        </message>
        <message>
            <source>Add &amp;Global Variable List...</source>
            <translation>添加全局变量列表(&amp;G)...</translation>
        </message>
        <message>
            <source>Task &amp;Configuration</source>
            <translation>任务配置(&amp;C)</translation>
        </message>
        <message>
            <source>Add Global Variable List</source>
            <translation>添加全局变量列表</translation>
        </message>
        <message>
            <source>Add &amp;Method...</source>
            <translation>添加方法(&amp;M)...</translation>
        </message>
        <message>
            <source>Add Propert&amp;y...</source>
            <translation>添加属性(&amp;Y)...</translation>
        </message>
        <message>
            <source>Add Property</source>
            <translation>添加属性</translation>
        </message>
        <message>
            <source>Add Method</source>
            <translation>添加方法</translation>
        </message>
        <message>
            <source>Add &amp;Interface...</source>
            <translation>添加接口(&amp;I)...</translation>
        </message>
        <message>
            <source>Add Interface</source>
            <translation>添加接口</translation>
        </message>
    </context>
    <context>
        <name>iec::app::ProjectTreeModel</name>
        <message>
            <source>Programs</source>
            <translation>程序</translation>
        </message>
        <message>
            <source>Function Blocks</source>
            <translation>功能块</translation>
        </message>
        <message>
            <source>Functions</source>
            <translation>函数</translation>
        </message>
        <message>
            <source>Data Types</source>
            <translation>数据类型</translation>
        </message>
        <message>
            <source>Global Variables</source>
            <translation>全局变量</translation>
        </message>
        <message>
            <source>Configurations</source>
            <translation>配置</translation>
        </message>
        <message>
            <source>%1 (PRG)</source>
            <translation>%1 (PRG)</translation>
        </message>
        <message>
            <source>%1 (FB)</source>
            <translation>%1 (FB)</translation>
        </message>
        <message>
            <source>%1 (FUN)</source>
            <translation>%1 (FUN)</translation>
        </message>
        <message>
            <source>%1, written in %2</source>
            <translation>%1，使用 %2 编写</translation>
        </message>
        <message>
            <source>Structured Text (ST)</source>
            <translation>结构化文本 (ST)</translation>
        </message>
        <message>
            <source>Instruction List (IL)</source>
            <translation>指令表 (IL)</translation>
        </message>
        <message>
            <source>Ladder Diagram (LD)</source>
            <translation>梯形图 (LD)</translation>
        </message>
        <message>
            <source>Function Block Diagram (FBD)</source>
            <translation>功能块图 (FBD)</translation>
        </message>
        <message>
            <source>Sequential Function Chart (SFC)</source>
            <translation>顺序功能图 (SFC)</translation>
        </message>
        <message>
            <source>Continuous Function Chart (CFC)</source>
            <translation>连续功能图 (CFC)</translation>
        </message>
        <message>
            <source>%1 (PROPERTY)</source>
            <translation>%1 (属性)</translation>
        </message>
        <message>
            <source>%1 (METHOD)</source>
            <translation>%1 (方法)</translation>
        </message>
        <message>
            <source>Edited as text: METHOD ... END_METHOD or PROPERTY ... END_PROPERTY</source>
            <translation>以文本编辑：METHOD ... END_METHOD 或 PROPERTY ... END_PROPERTY</translation>
        </message>
        <message>
            <source>Interfaces</source>
            <translation>接口</translation>
        </message>
        <message>
            <source>%1 (ITF)</source>
            <translation>%1 (ITF)</translation>
        </message>
        <message>
            <source>Edited as text: INTERFACE ... END_INTERFACE</source>
            <translation>以文本编辑：INTERFACE ... END_INTERFACE</translation>
        </message>
    </context>
    <context>
        <name>iec::app::RecentFilesMenu</name>
        <message>
            <source>(none)</source>
            <translation>(无)</translation>
        </message>
    </context>
    <context>
        <name>iec::app::RecoveryManager</name>
        <message>
            <source>Cannot create the folder %1.</source>
            <translation>无法创建文件夹 %1。</translation>
        </message>
    </context>
    <context>
        <name>iec::app::RenameDialog</name>
        <message>
            <source>Rename %1</source>
            <translation>重命名 %1</translation>
        </message>
        <message>
            <source>&amp;New name:</source>
            <translation>新名称(&amp;N)：</translation>
        </message>
    </context>
    <context>
        <name>iec::app::RuntimeWorker</name>
        <message>
            <source>There is no variable called %1.</source>
            <translation>没有名为 %1 的变量。</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1：%2</translation>
        </message>
    </context>
    <context>
        <name>iec::app::SearchActions</name>
        <message>
            <source>Find in &amp;Project...</source>
            <translation>在项目中查找(&amp;P)...</translation>
        </message>
        <message>
            <source>&amp;Go to Definition</source>
            <translation>转到定义(&amp;G)</translation>
        </message>
        <message>
            <source>Cross &amp;References</source>
            <translation>交叉引用(&amp;R)</translation>
        </message>
        <message>
            <source>%1 matches of "%2"</source>
            <translation>"%2" 的 %1 个匹配项</translation>
        </message>
        <message>
            <source>Cross references of %1: %2 places</source>
            <translation>%1 的交叉引用：%2 处</translation>
        </message>
    </context>
    <context>
        <name>iec::app::SearchResultsPane</name>
        <message>
            <source>declaration</source>
            <translation>声明</translation>
        </message>
        <message>
            <source>element %1</source>
            <translation>元素 %1</translation>
        </message>
        <message>
            <source>line %1, column %2</source>
            <translation>第 %1 行，第 %2 列</translation>
        </message>
        <message>
            <source>Place</source>
            <translation>位置</translation>
        </message>
        <message>
            <source>Where</source>
            <translation>所在处</translation>
        </message>
        <message>
            <source>Use</source>
            <translation>用法</translation>
        </message>
        <message>
            <source>Text</source>
            <translation>文本</translation>
        </message>
    </context>
    <context>
        <name>iec::app::SettingsDialog</name>
        <message>
            <source>Settings</source>
            <translation>设置</translation>
        </message>
        <message>
            <source>System language</source>
            <translation>系统语言</translation>
        </message>
        <message>
            <source> pt</source>
            <translation> 磅</translation>
        </message>
        <message>
            <source> px</source>
            <translation> 像素</translation>
        </message>
        <message>
            <source> min</source>
            <translation> 分钟</translation>
        </message>
        <message>
            <source>Off</source>
            <translation>关闭</translation>
        </message>
        <message>
            <source>User interface language:</source>
            <translation>界面语言：</translation>
        </message>
        <message>
            <source>Editor font:</source>
            <translation>编辑器字体：</translation>
        </message>
        <message>
            <source>Editor font size:</source>
            <translation>编辑器字号：</translation>
        </message>
        <message>
            <source>Diagram grid size:</source>
            <translation>图形网格大小：</translation>
        </message>
        <message>
            <source>Autosave every:</source>
            <translation>自动保存间隔：</translation>
        </message>
    </context>
    <context>
        <name>iec::app::TraceExport</name>
        <message>
            <source>%1 cannot be written: %2</source>
            <translation>无法写入 %1：%2</translation>
        </message>
        <message>
            <source>%1 cannot be written.</source>
            <translation>无法写入 %1。</translation>
        </message>
        <message>
            <source>Nothing was recorded yet: choose variables, log in and run the program.</source>
            <translation>尚未记录任何内容：请选择变量，登录并运行程序。</translation>
        </message>
        <message>
            <source>%1: a trace is exported as .csv, .vcd, .png or .pdf.</source>
            <translation>%1：跟踪可导出为 .csv、.vcd、.png 或 .pdf。</translation>
        </message>
    </context>
    <context>
        <name>iec::app::TracePane</name>
        <message>
            <source>Trace</source>
            <translation>跟踪</translation>
        </message>
        <message>
            <source>Configure...</source>
            <translation>配置...</translation>
        </message>
        <message>
            <source>Choose the variables, the trigger and how often to sample</source>
            <translation>选择变量、触发条件和采样频率</translation>
        </message>
        <message>
            <source>Add Variable...</source>
            <translation>添加变量...</translation>
        </message>
        <message>
            <source>Pause</source>
            <translation>暂停</translation>
        </message>
        <message>
            <source>Restart</source>
            <translation>重新开始</translation>
        </message>
        <message>
            <source>Drop the samples and record again (the trigger is armed again)</source>
            <translation>丢弃采样并重新记录（重新启用触发）</translation>
        </message>
        <message>
            <source>Zoom In</source>
            <translation>放大</translation>
        </message>
        <message>
            <source>Zoom Out</source>
            <translation>缩小</translation>
        </message>
        <message>
            <source>Fit</source>
            <translation>适合窗口</translation>
        </message>
        <message>
            <source>Show every sample and follow the newest</source>
            <translation>显示全部采样并跟随最新值</translation>
        </message>
        <message>
            <source>Export</source>
            <translation>导出</translation>
        </message>
        <message>
            <source>CSV (spreadsheet)...</source>
            <translation>CSV（电子表格）...</translation>
        </message>
        <message>
            <source>VCD (GTKWave)...</source>
            <translation>VCD（GTKWave）...</translation>
        </message>
        <message>
            <source>PNG picture...</source>
            <translation>PNG 图片...</translation>
        </message>
        <message>
            <source>PDF for a lab report...</source>
            <translation>PDF（实验报告用）...</translation>
        </message>
        <message>
            <source>Remove from Trace</source>
            <translation>从跟踪中移除</translation>
        </message>
        <message>
            <source>Cursor 1</source>
            <translation>光标 1</translation>
        </message>
        <message>
            <source>Cursor 2</source>
            <translation>光标 2</translation>
        </message>
        <message>
            <source>Difference</source>
            <translation>差值</translation>
        </message>
        <message>
            <source>Tick to show a lane, drag to reorder. In the chart: click for cursor 1, Shift+click for cursor 2, wheel to zoom.</source>
            <translation>勾选以显示通道，拖动以调整顺序。在图中：单击设置光标 1，Shift+单击设置光标 2，滚轮缩放。</translation>
        </message>
        <message>
            <source>Time (ms)</source>
            <translation>时间 (ms)</translation>
        </message>
        <message>
            <source>Cycle</source>
            <translation>周期</translation>
        </message>
        <message>
            <source>Nothing to record: choose variables with Configure... or Add Variable...</source>
            <translation>没有可记录的内容：请用“配置...”或“添加变量...”选择变量</translation>
        </message>
        <message numerus="yes">
            <source>%n sample(s)</source>
            <translation>
                <numerusform>%n 个采样</numerusform>
            </translation>
        </message>
        <message>
            <source>Offline: the trace records while you are logged in.</source>
            <translation>离线：登录后才会记录跟踪。</translation>
        </message>
        <message>
            <source>Offline: %1 from the last session.</source>
            <translation>离线：上次会话的 %1。</translation>
        </message>
        <message>
            <source>The record condition cannot be evaluated: %1</source>
            <translation>无法计算记录条件：%1</translation>
        </message>
        <message>
            <source>Recording: %1.</source>
            <translation>正在记录：%1。</translation>
        </message>
        <message>
            <source>Waiting for the trigger on %1: %2 kept before it.</source>
            <translation>等待 %1 的触发：触发前已保存 %2。</translation>
        </message>
        <message>
            <source>Triggered in cycle %1: recording what follows (%2).</source>
            <translation>已在第 %1 周期触发：正在记录之后的数据（%2）。</translation>
        </message>
        <message>
            <source>Triggered in cycle %1: done, %2. Restart arms the trigger again.</source>
            <translation>已在第 %1 周期触发：完成，%2。“重新开始”会重新启用触发。</translation>
        </message>
        <message>
            <source>Paused: %1.</source>
            <translation>已暂停：%1。</translation>
        </message>
        <message>
            <source>None of the chosen variables can be recorded (see Messages).</source>
            <translation>所选变量都无法记录（见消息窗口）。</translation>
        </message>
        <message>
            <source>Add Variable</source>
            <translation>添加变量</translation>
        </message>
        <message>
            <source>Variable to trace (e.g. Main.Level or a global):</source>
            <translation>要跟踪的变量（例如 Main.Level 或全局变量）：</translation>
        </message>
        <message>
            <source>Trace of %1, %2</source>
            <translation>%1 的跟踪，%2</translation>
        </message>
        <message>
            <source>the project</source>
            <translation>项目</translation>
        </message>
        <message>
            <source>CSV files (*.csv)</source>
            <translation>CSV 文件 (*.csv)</translation>
        </message>
        <message>
            <source>Value change dumps (*.vcd)</source>
            <translation>值变化转储 (*.vcd)</translation>
        </message>
        <message>
            <source>PNG pictures (*.png)</source>
            <translation>PNG 图片 (*.png)</translation>
        </message>
        <message>
            <source>PDF documents (*.pdf)</source>
            <translation>PDF 文档 (*.pdf)</translation>
        </message>
        <message>
            <source>Export Trace</source>
            <translation>导出跟踪</translation>
        </message>
    </context>
    <context>
        <name>iec::app::TraceSettingsDialog</name>
        <message>
            <source>Trace Configuration</source>
            <translation>跟踪配置</translation>
        </message>
        <message>
            <source>One variable per line, e.g. Main.Level</source>
            <translation>每行一个变量，例如 Main.Level</translation>
        </message>
        <message>
            <source> cycle(s)</source>
            <translation> 个周期</translation>
        </message>
        <message>
            <source>None (record all the time)</source>
            <translation>无（一直记录）</translation>
        </message>
        <message>
            <source>Rising edge</source>
            <translation>上升沿</translation>
        </message>
        <message>
            <source>Falling edge</source>
            <translation>下降沿</translation>
        </message>
        <message>
            <source>Level reached</source>
            <translation>达到电平</translation>
        </message>
        <message>
            <source>e.g. Main.Start</source>
            <translation>例如 Main.Start</translation>
        </message>
        <message>
            <source>A BOOL is 1 when TRUE: the level 0.5 triggers on its edges.</source>
            <translation>BOOL 为 TRUE 时等于 1：电平 0.5 在其边沿触发。</translation>
        </message>
        <message>
            <source>Record only while TRUE, e.g. Main.Running</source>
            <translation>仅在为 TRUE 时记录，例如 Main.Running</translation>
        </message>
        <message>
            <source> scans</source>
            <translation> 次扫描</translation>
        </message>
        <message>
            <source>&amp;Variables:</source>
            <translation>变量(&amp;V)：</translation>
        </message>
        <message>
            <source>Sample &amp;every:</source>
            <translation>采样间隔(&amp;E)：</translation>
        </message>
        <message>
            <source>Samples &amp;kept:</source>
            <translation>保存采样数(&amp;K)：</translation>
        </message>
        <message>
            <source>&amp;Trigger:</source>
            <translation>触发(&amp;T)：</translation>
        </message>
        <message>
            <source>Trigger v&amp;ariable:</source>
            <translation>触发变量(&amp;A)：</translation>
        </message>
        <message>
            <source>Trigger &amp;level:</source>
            <translation>触发电平(&amp;L)：</translation>
        </message>
        <message>
            <source>Samples &amp;after the trigger:</source>
            <translation>触发后采样数(&amp;A)：</translation>
        </message>
        <message>
            <source>Record &amp;condition:</source>
            <translation>记录条件(&amp;C)：</translation>
        </message>
        <message>
            <source>&amp;Scan history keeps:</source>
            <translation>扫描历史保存(&amp;S)：</translation>
        </message>
        <message>
            <source>The record condition is not an expression: %1</source>
            <translation>记录条件不是表达式：%1</translation>
        </message>
        <message>
            <source>Name the variable that triggers the recording.</source>
            <translation>请指定触发记录的变量。</translation>
        </message>
    </context>
    <context>
        <name>iec::app::UndoActions</name>
        <message>
            <source>&amp;Undo Typing</source>
            <translation>撤销输入(&amp;U)</translation>
        </message>
        <message>
            <source>&amp;Redo Typing</source>
            <translation>重做输入(&amp;R)</translation>
        </message>
        <message>
            <source>&amp;Undo %1</source>
            <translation>撤销 %1(&amp;U)</translation>
        </message>
        <message>
            <source>&amp;Undo</source>
            <translation>撤销(&amp;U)</translation>
        </message>
        <message>
            <source>&amp;Redo %1</source>
            <translation>重做 %1(&amp;R)</translation>
        </message>
        <message>
            <source>&amp;Redo</source>
            <translation>重做(&amp;R)</translation>
        </message>
    </context>
    <context>
        <name>iec::app::WatchModel</name>
        <message>
            <source>(no such variable)</source>
            <translation>(无此变量)</translation>
        </message>
        <message>
            <source>%1 (forced)</source>
            <translation>%1(已强制)</translation>
        </message>
        <message>
            <source>Type the value to write or force, then choose Write or Force.</source>
            <translation>输入要写入或强制的值,然后选择“写入”或“强制”。</translation>
        </message>
        <message>
            <source>Expression</source>
            <translation>表达式</translation>
        </message>
        <message>
            <source>Type</source>
            <translation>类型</translation>
        </message>
        <message>
            <source>Value</source>
            <translation>值</translation>
        </message>
        <message>
            <source>Prepared value</source>
            <translation>预备值</translation>
        </message>
        <message>
            <source>Value after scan %1 (history)</source>
            <translation>第 %1 次扫描后的值（历史）</translation>
        </message>
    </context>
    <context>
        <name>iec::app::WatchPane</name>
        <message>
            <source>Variable to watch, e.g. Main.Counter</source>
            <translation>要监视的变量,例如 Main.Counter</translation>
        </message>
        <message>
            <source>Add</source>
            <translation>添加</translation>
        </message>
        <message>
            <source>Write</source>
            <translation>写入</translation>
        </message>
        <message>
            <source>Write the prepared values once, at the start of the next cycle (Ctrl+F7)</source>
            <translation>在下一个周期开始时写入一次预备值 (Ctrl+F7)</translation>
        </message>
        <message>
            <source>Force</source>
            <translation>强制</translation>
        </message>
        <message>
            <source>Hold the prepared values every cycle until released (F7)</source>
            <translation>在每个周期保持预备值,直到释放 (F7)</translation>
        </message>
        <message>
            <source>Release</source>
            <translation>释放</translation>
        </message>
        <message>
            <source>Release the forces of the selected variables (Alt+F7)</source>
            <translation>释放所选变量的强制 (Alt+F7)</translation>
        </message>
        <message>
            <source>Release All</source>
            <translation>全部释放</translation>
        </message>
        <message>
            <source>Remove</source>
            <translation>移除</translation>
        </message>
    </context>
    <context>
        <name>iec::app::WindowMenu</name>
        <message>
            <source>&amp;Next Document</source>
            <translation>下一个文档(&amp;N)</translation>
        </message>
        <message>
            <source>&amp;Previous Document</source>
            <translation>上一个文档(&amp;P)</translation>
        </message>
        <message>
            <source>&amp;Close All Documents</source>
            <translation>关闭所有文档(&amp;C)</translation>
        </message>
    </context>
    <context>
        <name>iec::editors</name>
        <message>
            <source>There is nothing to paste.</source>
            <translation>没有可粘贴的内容。</translation>
        </message>
        <message>
            <source>The clipboard holds text, not %1 elements: nothing was pasted.</source>
            <translation>剪贴板中是文本，不是 %1 元素：未粘贴任何内容。</translation>
        </message>
        <message>
            <source>The clipboard holds no %1 elements that can be pasted. %2</source>
            <translation>剪贴板中没有可粘贴的 %1 元素。%2</translation>
        </message>
        <message>
            <source>The clipboard holds %1 elements, which cannot be pasted into %2.</source>
            <translation>剪贴板中是 %1 元素，不能粘贴到 %2 中。</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::AliasPage</name>
        <message>
            <source>Base type:</source>
            <translation>基本类型：</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::ArrayPage</name>
        <message>
            <source>Low</source>
            <translation>下限</translation>
        </message>
        <message>
            <source>High</source>
            <translation>上限</translation>
        </message>
        <message>
            <source>Dimensions</source>
            <translation>维数</translation>
        </message>
        <message>
            <source>Element type:</source>
            <translation>元素类型：</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::CodeEditor</name>
        <message>
            <source>Go to Definition</source>
            <translation>转到定义</translation>
        </message>
        <message>
            <source>Complete</source>
            <translation>自动完成</translation>
        </message>
        <message>
            <source>Input Assistant...</source>
            <translation>输入助手...</translation>
        </message>
        <message>
            <source>Toggle Comment</source>
            <translation>切换注释</translation>
        </message>
        <message>
            <source>Fold All</source>
            <translation>全部折叠</translation>
        </message>
        <message>
            <source>Unfold All</source>
            <translation>全部展开</translation>
        </message>
        <message>
            <source>Add to Watch</source>
            <translation>添加到监视</translation>
        </message>
        <message>
            <source>The program is online, so its text cannot be changed. Choose Online &gt; Logout to edit it.</source>
            <translation>程序处于在线状态,不能修改其文本。请选择“在线 &gt; 注销”后再编辑。</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::ConfigurationEditor</name>
        <message>
            <source>Configuration %1</source>
            <translation>配置 %1</translation>
        </message>
        <message>
            <source>Resource:</source>
            <translation>资源：</translation>
        </message>
        <message>
            <source>Resource name</source>
            <translation>资源名称</translation>
        </message>
        <message>
            <source>Add Resource</source>
            <translation>添加资源</translation>
        </message>
        <message>
            <source>Remove Resource</source>
            <translation>移除资源</translation>
        </message>
        <message>
            <source>Tasks (the lower the priority number, the earlier the task runs)</source>
            <translation>任务（优先级数字越小，任务越先执行）</translation>
        </message>
        <message>
            <source>Task</source>
            <translation>任务</translation>
        </message>
        <message>
            <source>Interval (cyclic)</source>
            <translation>间隔（循环）</translation>
        </message>
        <message>
            <source>SINGLE (event variable)</source>
            <translation>SINGLE（事件变量）</translation>
        </message>
        <message>
            <source>Priority</source>
            <translation>优先级</translation>
        </message>
        <message>
            <source>Watchdog</source>
            <translation>看门狗</translation>
        </message>
        <message>
            <source>The task's name, unique in the configuration.</source>
            <translation>任务名称，在配置中必须唯一。</translation>
        </message>
        <message>
            <source>The task runs every interval (T#10ms). With neither an interval nor a SINGLE variable it runs in every cycle (CODESYS: freewheeling).</source>
            <translation>任务按间隔 (T#10ms) 周期执行。既无间隔也无 SINGLE 变量时，任务在每个周期都执行（CODESYS：自由运行）。</translation>
        </message>
        <message>
            <source>A global BOOL variable: the task runs once each time it becomes TRUE (CODESYS: triggered by event).</source>
            <translation>一个全局 BOOL 变量：每当它变为 TRUE 时，任务执行一次（CODESYS：事件触发）。</translation>
        </message>
        <message>
            <source>0 is the highest priority; tasks due in the same cycle run in the order of their priorities.</source>
            <translation>0 为最高优先级；在同一周期内到期的任务按优先级顺序执行。</translation>
        </message>
        <message>
            <source>The longest time one run of the task may take (T#50ms); empty for none. It is kept in the project for the target; the simulator does not check it.</source>
            <translation>任务单次执行允许的最长时间 (T#50ms)；留空表示不设置。该值保存在项目中供目标系统使用；仿真器不检查它。</translation>
        </message>
        <message>
            <source>Instance</source>
            <translation>实例</translation>
        </message>
        <message>
            <source>Program</source>
            <translation>程序</translation>
        </message>
        <message>
            <source>Global variable lists of the resource (double-click opens one)</source>
            <translation>该资源的全局变量列表（双击打开）</translation>
        </message>
        <message>
            <source>Add List...</source>
            <translation>添加列表...</translation>
        </message>
        <message>
            <source>Programs run by task %1</source>
            <translation>由任务 %1 执行的程序</translation>
        </message>
        <message>
            <source>Programs run by the task</source>
            <translation>由该任务执行的程序</translation>
        </message>
        <message>
            <source>Change tasks of %1</source>
            <translation>修改 %1 的任务</translation>
        </message>
        <message>
            <source>Change programs of task %1</source>
            <translation>修改任务 %1 的程序</translation>
        </message>
        <message>
            <source>Rename resource %1 to %2</source>
            <translation>将资源 %1 重命名为 %2</translation>
        </message>
        <message>
            <source>Add resource %1</source>
            <translation>添加资源 %1</translation>
        </message>
        <message>
            <source>Remove resource %1</source>
            <translation>移除资源 %1</translation>
        </message>
        <message>
            <source>Resource %1: %2</source>
            <translation>资源 %1：%2</translation>
        </message>
        <message>
            <source>Task %1: %2</source>
            <translation>任务 %1：%2</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::DataTypeEditor</name>
        <message>
            <source>Name:</source>
            <translation>名称:</translation>
        </message>
        <message>
            <source>Kind:</source>
            <translation>类别：</translation>
        </message>
        <message>
            <source>Initial value:</source>
            <translation>初始值：</translation>
        </message>
        <message>
            <source>(the default of the type)</source>
            <translation>(该类型的默认值)</translation>
        </message>
        <message>
            <source>Structure</source>
            <translation>结构体</translation>
        </message>
        <message>
            <source>Enumeration</source>
            <translation>枚举</translation>
        </message>
        <message>
            <source>Array</source>
            <translation>数组</translation>
        </message>
        <message>
            <source>Subrange</source>
            <translation>子范围</translation>
        </message>
        <message>
            <source>Alias</source>
            <translation>别名</translation>
        </message>
        <message>
            <source>String</source>
            <translation>字符串</translation>
        </message>
        <message>
            <source>IEC text:</source>
            <translation>IEC 文本：</translation>
        </message>
        <message>
            <source>IEC text as last applied (correct the marked fields to apply):</source>
            <translation>最近一次应用的 IEC 文本(请更正标记的字段以应用)：</translation>
        </message>
        <message>
            <source>Rename member %1 to %2</source>
            <translation>将成员 %1 重命名为 %2</translation>
        </message>
        <message numerus="yes">
            <source>Rename %n member(s)</source>
            <translation>
                <numerusform>重命名 %n 个成员</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>iec::editors::DataTypeValidator</name>
        <message>
            <source>A POU or data type named "%1" exists already.</source>
            <translation>名为 "%1" 的 POU 或数据类型已存在。</translation>
        </message>
        <message>
            <source>A structure needs at least one member.</source>
            <translation>结构体至少需要一个成员。</translation>
        </message>
        <message>
            <source>There is a member named "%1" already.</source>
            <translation>已有名为 "%1" 的成员。</translation>
        </message>
        <message>
            <source>An enumeration needs at least one value.</source>
            <translation>枚举至少需要一个值。</translation>
        </message>
        <message>
            <source>The value "%1" is listed already.</source>
            <translation>值 "%1" 已列出。</translation>
        </message>
        <message>
            <source>Enter a whole number, or leave it empty.</source>
            <translation>请输入整数，或留空。</translation>
        </message>
        <message>
            <source>An array needs at least one dimension.</source>
            <translation>数组至少需要一个维。</translation>
        </message>
        <message>
            <source>Enter a length from 1 to 65535, or leave it empty for the default.</source>
            <translation>请输入 1 到 65535 之间的长度，或留空使用默认值。</translation>
        </message>
        <message>
            <source>Choose an integer type such as INT, DINT or UINT.</source>
            <translation>请选择整数类型，如 INT、DINT 或 UINT。</translation>
        </message>
        <message>
            <source>The upper bound %1 is less than the lower bound %2.</source>
            <translation>上限 %1 小于下限 %2。</translation>
        </message>
        <message>
            <source>Enter a bound.</source>
            <translation>请输入边界。</translation>
        </message>
        <message>
            <source>Enter a whole number or the name of a constant.</source>
            <translation>请输入整数或常量名称。</translation>
        </message>
        <message>
            <source>Enter a type.</source>
            <translation>请输入类型。</translation>
        </message>
        <message>
            <source>"%1" is not a type.</source>
            <translation>"%1" 不是类型。</translation>
        </message>
        <message>
            <source>A type cannot contain itself.</source>
            <translation>类型不能包含自身。</translation>
        </message>
        <message>
            <source>Unknown type "%1".</source>
            <translation>未知类型 "%1"。</translation>
        </message>
        <message>
            <source>"%1" is not a valid initial value.</source>
            <translation>"%1" 不是有效的初始值。</translation>
        </message>
        <message>
            <source>Enter a name.</source>
            <translation>请输入名称。</translation>
        </message>
        <message>
            <source>"%1" is not an IEC identifier: use letters, digits and single underscores, starting with a letter or an underscore and not ending with an underscore.</source>
            <translation>"%1" 不是 IEC 标识符：只能使用字母、数字和单个下划线，以字母或下划线开头，且不能以下划线结尾。</translation>
        </message>
        <message>
            <source>"%1" is a reserved word of IEC 61131-3.</source>
            <translation>"%1" 是 IEC 61131-3 的保留字。</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::DeclarationEditor</name>
        <message>
            <source>Table</source>
            <translation>表格</translation>
        </message>
        <message>
            <source>Text</source>
            <translation>文本</translation>
        </message>
        <message>
            <source>Add Variable</source>
            <translation>添加变量</translation>
        </message>
        <message>
            <source>Remove</source>
            <translation>移除</translation>
        </message>
        <message>
            <source>Move Up</source>
            <translation>上移</translation>
        </message>
        <message>
            <source>Move Down</source>
            <translation>下移</translation>
        </message>
        <message>
            <source>Row %1: %2</source>
            <translation>第 %1 行：%2</translation>
        </message>
        <message>
            <source>Line %1, column %2: %3</source>
            <translation>第 %1 行，第 %2 列：%3</translation>
        </message>
        <message>
            <source>Rename variable %1 to %2</source>
            <translation>将变量 %1 重命名为 %2</translation>
        </message>
        <message numerus="yes">
            <source>Rename %n variable(s)</source>
            <translation>
                <numerusform>重命名 %n 个变量</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>iec::editors::DeclarationRows</name>
        <message>
            <source>"%1" is not a variable class.</source>
            <translation>"%1" 不是变量类别。</translation>
        </message>
        <message>
            <source>"%1" is not a data type.</source>
            <translation>"%1" 不是数据类型。</translation>
        </message>
        <message>
            <source>"%1" is not an initial value for %2.</source>
            <translation>"%1" 不是 %2 的初始值。</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::DeclarationTableModel</name>
        <message>
            <source>Name</source>
            <translation>名称</translation>
        </message>
        <message>
            <source>Class</source>
            <translation>类别</translation>
        </message>
        <message>
            <source>Type</source>
            <translation>类型</translation>
        </message>
        <message>
            <source>Initial Value</source>
            <translation>初始值</translation>
        </message>
        <message>
            <source>Address</source>
            <translation>地址</translation>
        </message>
        <message>
            <source>Comment</source>
            <translation>注释</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::DeclarationText</name>
        <message>
            <source>VAR_ACCESS and VAR_CONFIG belong in a configuration, not in a POU.</source>
            <translation>VAR_ACCESS 和 VAR_CONFIG 属于配置，而不属于 POU。</translation>
        </message>
        <message>
            <source>"%1" is not a valid name: use letters, digits and single underscores, and no keyword.</source>
            <translation>"%1" 不是有效的名称：请使用字母、数字和单个下划线，且不能是关键字。</translation>
        </message>
        <message>
            <source>"%1" is not an address such as %IX0.0, %QW3 or %MD10.</source>
            <translation>"%1" 不是地址(例如 %IX0.0、%QW3 或 %MD10)。</translation>
        </message>
        <message>
            <source>%1 is declared twice.</source>
            <translation>%1 被声明了两次。</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::DiagramEditor</name>
        <message>
            <source>Zoom In</source>
            <translation>放大</translation>
        </message>
        <message>
            <source>Zoom Out</source>
            <translation>缩小</translation>
        </message>
        <message>
            <source>Fit to Window</source>
            <translation>适合窗口</translation>
        </message>
        <message>
            <source>Export Picture…</source>
            <translation>导出图片…</translation>
        </message>
        <message>
            <source>Print…</source>
            <translation>打印…</translation>
        </message>
        <message>
            <source>The diagram cannot be changed while online. Log out first (Online → Logout).</source>
            <translation>在线时不能修改图形。请先注销（在线 → 注销）。</translation>
        </message>
        <message>
            <source>This body cannot be edited here.</source>
            <translation>此程序体不能在这里编辑。</translation>
        </message>
        <message>
            <source>Export Picture</source>
            <translation>导出图片</translation>
        </message>
        <message>
            <source>SVG picture (*.svg);;PNG picture (*.png);;PDF document (*.pdf)</source>
            <translation>SVG 图片 (*.svg);;PNG 图片 (*.png);;PDF 文档 (*.pdf)</translation>
        </message>
        <message>
            <source>Zoom 100 %</source>
            <translation>缩放 100 %</translation>
        </message>
        <message>
            <source>Export…</source>
            <translation>导出…</translation>
        </message>
        <message>
            <source>Zoom +</source>
            <translation>放大</translation>
        </message>
        <message>
            <source>Zoom −</source>
            <translation>缩小</translation>
        </message>
        <message>
            <source>Fit</source>
            <translation>适合窗口</translation>
        </message>
        <message>
            <source>Prepare Value</source>
            <translation>准备数值</translation>
        </message>
        <message>
            <source>New value of %1 (now %2):</source>
            <translation>%1 的新值(当前 %2):</translation>
        </message>
        <message>
            <source>Prepared %1 := %2. Write it with Ctrl+F7 or force it with F7.</source>
            <translation>已准备 %1 := %2。按 Ctrl+F7 写入,或按 F7 强制。</translation>
        </message>
        <message>
            <source>network %1</source>
            <translation>网络 %1</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::DiagramExport</name>
        <message>
            <source>Cannot write %1.</source>
            <translation>无法写入 %1。</translation>
        </message>
        <message>
            <source>Unknown picture type '%1': use .svg, .png or .pdf.</source>
            <translation>未知的图片类型 '%1':请使用 .svg、.png 或 .pdf。</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::EnumPage</name>
        <message>
            <source>Name</source>
            <translation>名称</translation>
        </message>
        <message>
            <source>Value (optional)</source>
            <translation>值(可选)</translation>
        </message>
        <message>
            <source>Values</source>
            <translation>值</translation>
        </message>
        <message>
            <source>Base type (optional):</source>
            <translation>基本类型(可选)：</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::FindReplaceBar</name>
        <message>
            <source>Find</source>
            <translation>查找</translation>
        </message>
        <message>
            <source>Replace with</source>
            <translation>替换为</translation>
        </message>
        <message>
            <source>Match case</source>
            <translation>区分大小写</translation>
        </message>
        <message>
            <source>Whole words</source>
            <translation>全字匹配</translation>
        </message>
        <message>
            <source>Previous</source>
            <translation>上一个</translation>
        </message>
        <message>
            <source>Next</source>
            <translation>下一个</translation>
        </message>
        <message>
            <source>Replace</source>
            <translation>替换</translation>
        </message>
        <message>
            <source>Replace All</source>
            <translation>全部替换</translation>
        </message>
        <message>
            <source>Close</source>
            <translation>关闭</translation>
        </message>
        <message>
            <source>Find:</source>
            <translation>查找：</translation>
        </message>
        <message>
            <source>Replace:</source>
            <translation>替换：</translation>
        </message>
        <message>
            <source>Not found</source>
            <translation>未找到</translation>
        </message>
        <message>
            <source>Search wrapped</source>
            <translation>已从头继续查找</translation>
        </message>
        <message numerus="yes">
            <source>%n replaced</source>
            <translation>
                <numerusform>已替换 %n 处</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>iec::editors::GlobalListEditor</name>
        <message>
            <source>Change global variable list %1</source>
            <translation>修改全局变量列表 %1</translation>
        </message>
        <message>
            <source>Rename global variable %1 to %2</source>
            <translation>将全局变量 %1 重命名为 %2</translation>
        </message>
        <message numerus="yes">
            <source>Rename %n global variable(s)</source>
            <translation>
                <numerusform>重命名 %n 个全局变量</numerusform>
            </translation>
        </message>
        <message>
            <source>A global variable list holds VAR_GLOBAL sections only; %1 belongs in a POU.</source>
            <translation>全局变量列表只能包含 VAR_GLOBAL 段；%1 应放在程序组织单元中。</translation>
        </message>
        <message>
            <source>%1 is declared in the global variable list %2 already.</source>
            <translation>%1 已在全局变量列表 %2 中声明。</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::InPlaceEditor</name>
        <message>
            <source>Enter applies, Esc cancels, F2 opens the input assistant.</source>
            <translation>回车确认，Esc 取消，F2 打开输入助手。</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::InputAssistantDialog</name>
        <message>
            <source>Input Assistant</source>
            <translation>输入助手</translation>
        </message>
        <message>
            <source>Operators</source>
            <translation>运算符</translation>
        </message>
        <message>
            <source>Operands</source>
            <translation>操作数</translation>
        </message>
        <message>
            <source>Functions</source>
            <translation>函数</translation>
        </message>
        <message>
            <source>Function blocks</source>
            <translation>功能块</translation>
        </message>
        <message>
            <source>Filter</source>
            <translation>筛选</translation>
        </message>
        <message>
            <source>Name</source>
            <translation>名称</translation>
        </message>
        <message>
            <source>Description</source>
            <translation>描述</translation>
        </message>
        <message>
            <source>IL operators</source>
            <translation>IL 运算符</translation>
        </message>
        <message>
            <source>ST operators</source>
            <translation>ST 运算符</translation>
        </message>
        <message>
            <source>Variables</source>
            <translation>变量</translation>
        </message>
        <message>
            <source>Boolean constants</source>
            <translation>布尔常量</translation>
        </message>
        <message>
            <source>User-defined functions</source>
            <translation>用户定义的函数</translation>
        </message>
        <message>
            <source>User-defined function blocks</source>
            <translation>用户定义的功能块</translation>
        </message>
        <message>
            <source>Programs</source>
            <translation>程序</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::NetworkDialogs</name>
        <message>
            <source>Network Label</source>
            <translation>节标号</translation>
        </message>
        <message>
            <source>Label of network %1 (empty: none):</source>
            <translation>第 %1 节的标号(留空:无):</translation>
        </message>
        <message>
            <source>Network Comment</source>
            <translation>节注释</translation>
        </message>
        <message>
            <source>Comment of network %1:</source>
            <translation>第 %1 节的注释:</translation>
        </message>
        <message>
            <source>Jump</source>
            <translation>跳转</translation>
        </message>
        <message>
            <source>Jump to the network with the label:</source>
            <translation>跳转到带有此标号的节:</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::RowTable</name>
        <message>
            <source>Add</source>
            <translation>添加</translation>
        </message>
        <message>
            <source>Add a row below the current one</source>
            <translation>在当前行下方添加一行</translation>
        </message>
        <message>
            <source>Remove</source>
            <translation>移除</translation>
        </message>
        <message>
            <source>Remove the current row</source>
            <translation>删除当前行</translation>
        </message>
        <message>
            <source>Up</source>
            <translation>上移</translation>
        </message>
        <message>
            <source>Move the current row up</source>
            <translation>将当前行上移</translation>
        </message>
        <message>
            <source>Down</source>
            <translation>下移</translation>
        </message>
        <message>
            <source>Move the current row down</source>
            <translation>将当前行下移</translation>
        </message>
        <message>
            <source>Row %1, %2: %3</source>
            <translation>第 %1 行，%2：%3</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::StandardLibrary</name>
        <message>
            <source>Arithmetic</source>
            <translation>算术</translation>
        </message>
        <message>
            <source>Numeric</source>
            <translation>数值</translation>
        </message>
        <message>
            <source>Bit shift</source>
            <translation>移位</translation>
        </message>
        <message>
            <source>Selection</source>
            <translation>选择</translation>
        </message>
        <message>
            <source>Comparison</source>
            <translation>比较</translation>
        </message>
        <message>
            <source>String</source>
            <translation>字符串</translation>
        </message>
        <message>
            <source>Type conversion</source>
            <translation>类型转换</translation>
        </message>
        <message>
            <source>Bistable</source>
            <translation>双稳态</translation>
        </message>
        <message>
            <source>Edge detection</source>
            <translation>边沿检测</translation>
        </message>
        <message>
            <source>Counters</source>
            <translation>计数器</translation>
        </message>
        <message>
            <source>Timers</source>
            <translation>定时器</translation>
        </message>
        <message>
            <source>Load the operand into the current result</source>
            <translation>将操作数装入当前结果</translation>
        </message>
        <message>
            <source>Store the current result in the operand</source>
            <translation>将当前结果存入操作数</translation>
        </message>
        <message>
            <source>Set the Boolean operand to TRUE if the current result is TRUE</source>
            <translation>当前结果为 TRUE 时将布尔操作数置位为 TRUE</translation>
        </message>
        <message>
            <source>Reset the Boolean operand to FALSE if the current result is TRUE</source>
            <translation>当前结果为 TRUE 时将布尔操作数复位为 FALSE</translation>
        </message>
        <message>
            <source>Bitwise AND</source>
            <translation>按位与</translation>
        </message>
        <message>
            <source>Bitwise OR</source>
            <translation>按位或</translation>
        </message>
        <message>
            <source>Bitwise exclusive OR</source>
            <translation>按位异或</translation>
        </message>
        <message>
            <source>Addition</source>
            <translation>加法</translation>
        </message>
        <message>
            <source>Subtraction</source>
            <translation>减法</translation>
        </message>
        <message>
            <source>Multiplication</source>
            <translation>乘法</translation>
        </message>
        <message>
            <source>Division</source>
            <translation>除法</translation>
        </message>
        <message>
            <source>Greater than (&gt;)</source>
            <translation>大于 (&gt;)</translation>
        </message>
        <message>
            <source>Greater than or equal (&gt;=)</source>
            <translation>大于等于 (&gt;=)</translation>
        </message>
        <message>
            <source>Equal (=)</source>
            <translation>等于 (=)</translation>
        </message>
        <message>
            <source>Not equal (&lt;&gt;)</source>
            <translation>不等于 (&lt;&gt;)</translation>
        </message>
        <message>
            <source>Less than or equal (&lt;=)</source>
            <translation>小于等于 (&lt;=)</translation>
        </message>
        <message>
            <source>Less than (&lt;)</source>
            <translation>小于 (&lt;)</translation>
        </message>
        <message>
            <source>Jump to the label</source>
            <translation>跳转到标号</translation>
        </message>
        <message>
            <source>Call a function block instance</source>
            <translation>调用功能块实例</translation>
        </message>
        <message>
            <source>Return to the calling POU</source>
            <translation>返回调用它的 POU</translation>
        </message>
        <message>
            <source>Evaluate the deferred operation</source>
            <translation>计算被推迟的运算</translation>
        </message>
        <message>
            <source>negated operand</source>
            <translation>取反的操作数</translation>
        </message>
        <message>
            <source>deferred until )</source>
            <translation>推迟到 ) 执行</translation>
        </message>
        <message>
            <source>only if the current result is TRUE</source>
            <translation>仅当当前结果为 TRUE 时</translation>
        </message>
        <message>
            <source>only if the current result is FALSE</source>
            <translation>仅当当前结果为 FALSE 时</translation>
        </message>
        <message>
            <source>Assignment</source>
            <translation>赋值</translation>
        </message>
        <message>
            <source>Modulo</source>
            <translation>取模</translation>
        </message>
        <message>
            <source>Negation</source>
            <translation>取反</translation>
        </message>
        <message>
            <source>Adds the inputs.</source>
            <translation>将各输入相加。</translation>
        </message>
        <message>
            <source>Subtracts IN2 from IN1.</source>
            <translation>IN1 减去 IN2。</translation>
        </message>
        <message>
            <source>Multiplies the inputs.</source>
            <translation>将各输入相乘。</translation>
        </message>
        <message>
            <source>Divides IN1 by IN2.</source>
            <translation>IN1 除以 IN2。</translation>
        </message>
        <message>
            <source>The remainder of IN1 divided by IN2.</source>
            <translation>IN1 除以 IN2 的余数。</translation>
        </message>
        <message>
            <source>Copies the input to the output.</source>
            <translation>将输入复制到输出。</translation>
        </message>
        <message>
            <source>IN1 raised to the power IN2.</source>
            <translation>IN1 的 IN2 次幂。</translation>
        </message>
        <message>
            <source>The absolute value.</source>
            <translation>绝对值。</translation>
        </message>
        <message>
            <source>The square root.</source>
            <translation>平方根。</translation>
        </message>
        <message>
            <source>The natural logarithm.</source>
            <translation>自然对数。</translation>
        </message>
        <message>
            <source>The logarithm to base 10.</source>
            <translation>以 10 为底的对数。</translation>
        </message>
        <message>
            <source>e raised to the power IN.</source>
            <translation>e 的 IN 次幂。</translation>
        </message>
        <message>
            <source>The sine (IN in radians).</source>
            <translation>正弦（IN 以弧度为单位）。</translation>
        </message>
        <message>
            <source>The cosine (IN in radians).</source>
            <translation>余弦（IN 以弧度为单位）。</translation>
        </message>
        <message>
            <source>The tangent (IN in radians).</source>
            <translation>正切（IN 以弧度为单位）。</translation>
        </message>
        <message>
            <source>The arc sine, in radians.</source>
            <translation>反正弦，以弧度为单位。</translation>
        </message>
        <message>
            <source>The arc cosine, in radians.</source>
            <translation>反余弦，以弧度为单位。</translation>
        </message>
        <message>
            <source>The arc tangent, in radians.</source>
            <translation>反正切，以弧度为单位。</translation>
        </message>
        <message>
            <source>The whole-number part of a REAL.</source>
            <translation>REAL 的整数部分。</translation>
        </message>
        <message>
            <source>Shifts the bits N places to the left.</source>
            <translation>将各位左移 N 位。</translation>
        </message>
        <message>
            <source>Shifts the bits N places to the right.</source>
            <translation>将各位右移 N 位。</translation>
        </message>
        <message>
            <source>Rotates the bits N places to the left.</source>
            <translation>将各位循环左移 N 位。</translation>
        </message>
        <message>
            <source>Rotates the bits N places to the right.</source>
            <translation>将各位循环右移 N 位。</translation>
        </message>
        <message>
            <source>IN0 when G is FALSE, IN1 when G is TRUE.</source>
            <translation>G 为 FALSE 时为 IN0，G 为 TRUE 时为 IN1。</translation>
        </message>
        <message>
            <source>The larger input.</source>
            <translation>较大的输入。</translation>
        </message>
        <message>
            <source>The smaller input.</source>
            <translation>较小的输入。</translation>
        </message>
        <message>
            <source>IN limited to the range MN..MX.</source>
            <translation>IN 限制在 MN..MX 范围内。</translation>
        </message>
        <message>
            <source>Input number K (IN0, IN1, ...).</source>
            <translation>第 K 个输入（IN0、IN1、...）。</translation>
        </message>
        <message>
            <source>TRUE when IN1 &gt; IN2.</source>
            <translation>IN1 &gt; IN2 时为 TRUE。</translation>
        </message>
        <message>
            <source>TRUE when IN1 &gt;= IN2.</source>
            <translation>IN1 &gt;= IN2 时为 TRUE。</translation>
        </message>
        <message>
            <source>TRUE when IN1 = IN2.</source>
            <translation>IN1 = IN2 时为 TRUE。</translation>
        </message>
        <message>
            <source>TRUE when IN1 &lt;&gt; IN2.</source>
            <translation>IN1 &lt;&gt; IN2 时为 TRUE。</translation>
        </message>
        <message>
            <source>TRUE when IN1 &lt;= IN2.</source>
            <translation>IN1 &lt;= IN2 时为 TRUE。</translation>
        </message>
        <message>
            <source>TRUE when IN1 &lt; IN2.</source>
            <translation>IN1 &lt; IN2 时为 TRUE。</translation>
        </message>
        <message>
            <source>The number of characters of STR.</source>
            <translation>STR 的字符数。</translation>
        </message>
        <message>
            <source>The first SIZE characters of STR.</source>
            <translation>STR 的前 SIZE 个字符。</translation>
        </message>
        <message>
            <source>The last SIZE characters of STR.</source>
            <translation>STR 的后 SIZE 个字符。</translation>
        </message>
        <message>
            <source>LEN characters of STR from position POS.</source>
            <translation>STR 中从位置 POS 开始的 LEN 个字符。</translation>
        </message>
        <message>
            <source>STR1 followed by STR2.</source>
            <translation>STR1 后接 STR2。</translation>
        </message>
        <message>
            <source>STR2 inserted into STR1 after position POS.</source>
            <translation>在 STR1 的位置 POS 之后插入 STR2。</translation>
        </message>
        <message>
            <source>STR without LEN characters from position POS.</source>
            <translation>从 STR 的位置 POS 起删除 LEN 个字符。</translation>
        </message>
        <message>
            <source>STR1 with L characters from position P replaced by STR2.</source>
            <translation>将 STR1 中从位置 P 起的 L 个字符替换为 STR2。</translation>
        </message>
        <message>
            <source>The position of STR2 in STR1 (0: not found).</source>
            <translation>STR2 在 STR1 中的位置（0：未找到）。</translation>
        </message>
        <message>
            <source>Bistable, set dominant: Q1 stays TRUE from SET1 until RESET.</source>
            <translation>双稳态，置位优先：Q1 从 SET1 起保持 TRUE，直到 RESET。</translation>
        </message>
        <message>
            <source>Bistable, reset dominant: Q1 stays TRUE from SET until RESET1.</source>
            <translation>双稳态，复位优先：Q1 从 SET 起保持 TRUE，直到 RESET1。</translation>
        </message>
        <message>
            <source>Q is TRUE for one cycle when CLK rises.</source>
            <translation>CLK 上升沿时 Q 在一个周期内为 TRUE。</translation>
        </message>
        <message>
            <source>Q is TRUE for one cycle when CLK falls.</source>
            <translation>CLK 下降沿时 Q 在一个周期内为 TRUE。</translation>
        </message>
        <message>
            <source>Counts rising edges of CU up; Q when CV reaches PV.</source>
            <translation>对 CU 的上升沿加计数；CV 达到 PV 时 Q 为 TRUE。</translation>
        </message>
        <message>
            <source>Counts rising edges of CD down from PV; Q when CV reaches 0.</source>
            <translation>从 PV 开始对 CD 的上升沿减计数；CV 达到 0 时 Q 为 TRUE。</translation>
        </message>
        <message>
            <source>Counts up (CU) and down (CD); QU when CV reaches PV, QD at 0.</source>
            <translation>加计数 (CU) 和减计数 (CD)；CV 达到 PV 时 QU 为 TRUE，为 0 时 QD 为 TRUE。</translation>
        </message>
        <message>
            <source>Pulse: Q is TRUE for PT after IN rises.</source>
            <translation>脉冲：IN 上升后 Q 在 PT 时间内为 TRUE。</translation>
        </message>
        <message>
            <source>On delay: Q follows IN after it was TRUE for PT.</source>
            <translation>接通延时：IN 为 TRUE 持续 PT 后，Q 跟随 IN。</translation>
        </message>
        <message>
            <source>Off delay: Q stays TRUE for PT after IN falls.</source>
            <translation>断开延时：IN 下降后 Q 在 PT 时间内保持 TRUE。</translation>
        </message>
        <message>
            <source>Converts %1 to %2.</source>
            <translation>将 %1 转换为 %2。</translation>
        </message>
        <message>
            <source>BCD conversion</source>
            <translation>BCD 转换</translation>
        </message>
        <message>
            <source>Bit and byte functions</source>
            <translation>位/字节函数</translation>
        </message>
        <message>
            <source>Mathematical helpers</source>
            <translation>数学辅助函数</translation>
        </message>
        <message>
            <source>Controllers</source>
            <translation>控制器</translation>
        </message>
        <message>
            <source>Signal generators</source>
            <translation>信号发生器</translation>
        </message>
        <message>
            <source>Function manipulators</source>
            <translation>函数处理器</translation>
        </message>
        <message>
            <source>Analog values</source>
            <translation>模拟量处理</translation>
        </message>
        <message>
            <source>Messages</source>
            <translation>消息</translation>
        </message>
        <message>
            <source>The two BCD digits of B as a number; -1 when a digit is not 0 to 9.</source>
            <translation>B 的两位 BCD 数字所表示的数；某位不在 0 到 9 之间时为 -1。</translation>
        </message>
        <message>
            <source>I as two BCD digits; 255 when I is not 0 to 99.</source>
            <translation>I 表示为两位 BCD 数字；I 不在 0 到 99 之间时为 255。</translation>
        </message>
        <message>
            <source>Bit N of X (bit 0 first).</source>
            <translation>X 的第 N 位（从第 0 位起）。</translation>
        </message>
        <message>
            <source>The eight inputs as the bits of a byte, B0 lowest.</source>
            <translation>把八个输入作为一个字节的各位，B0 为最低位。</translation>
        </message>
        <message>
            <source>X with bit N set to B.</source>
            <translation>把 X 的第 N 位设为 B。</translation>
        </message>
        <message>
            <source>The eight bits of B as outputs B0 to B7.</source>
            <translation>把 B 的八位作为输出 B0 到 B7。</translation>
        </message>
        <message>
            <source>The slope of IN per second; TM is the time since the last call in ms.</source>
            <translation>IN 每秒的变化率；TM 为距上次调用的时间（毫秒）。</translation>
        </message>
        <message>
            <source>Sums IN over time; TM is the time since the last call in ms.</source>
            <translation>对 IN 随时间积分；TM 为距上次调用的时间（毫秒）。</translation>
        </message>
        <message>
            <source>Maps IN linearly from IN_MIN..IN_MAX to OUT_MIN..OUT_MAX.</source>
            <translation>把 IN 从 IN_MIN..IN_MAX 线性映射到 OUT_MIN..OUT_MAX。</translation>
        </message>
        <message>
            <source>Minimum, maximum and average of the INT values since RESET.</source>
            <translation>自 RESET 以来 INT 值的最小值、最大值和平均值。</translation>
        </message>
        <message>
            <source>Minimum, maximum and average of the REAL values since RESET.</source>
            <translation>自 RESET 以来 REAL 值的最小值、最大值和平均值。</translation>
        </message>
        <message>
            <source>The variance of the values since RESET.</source>
            <translation>自 RESET 以来各值的方差。</translation>
        </message>
        <message>
            <source>PD controller: Y from the error SET_POINT - ACTUAL.</source>
            <translation>PD 控制器：由偏差 SET_POINT - ACTUAL 计算 Y。</translation>
        </message>
        <message>
            <source>PID controller: Y from the error SET_POINT - ACTUAL.</source>
            <translation>PID 控制器：由偏差 SET_POINT - ACTUAL 计算 Y。</translation>
        </message>
        <message>
            <source>PID controller for a fixed cycle of CYCLE seconds.</source>
            <translation>用于固定周期（CYCLE 秒）的 PID 控制器。</translation>
        </message>
        <message>
            <source>While ENABLE, OUT is TRUE for TIMEHIGH, then FALSE for TIMELOW, and so on.</source>
            <translation>ENABLE 为真时，OUT 先在 TIMEHIGH 内为 TRUE，再在 TIMELOW 内为 FALSE，如此往复。</translation>
        </message>
        <message>
            <source>A periodic signal of the shape MODE (triangle, sawtooth, rectangle, sine).</source>
            <translation>形状由 MODE 决定的周期信号（三角波、锯齿波、方波、正弦波）。</translation>
        </message>
        <message>
            <source>OUT on the characteristic curve through the points P.</source>
            <translation>通过各点 P 的特性曲线上的 OUT 值。</translation>
        </message>
        <message>
            <source>OUT follows IN, rising by ASCEND and falling by DESCEND at most per TIMEBASE.</source>
            <translation>OUT 跟随 IN，每个 TIMEBASE 最多上升 ASCEND、下降 DESCEND。</translation>
        </message>
        <message>
            <source>OUT becomes TRUE below LOW and FALSE above HIGH.</source>
            <translation>低于 LOW 时 OUT 变为 TRUE，高于 HIGH 时变为 FALSE。</translation>
        </message>
        <message>
            <source>O when IN is above HIGH, U when below LOW, IL when in between.</source>
            <translation>IN 高于 HIGH 时 O，低于 LOW 时 U，介于两者之间时 IL。</translation>
        </message>
        <message>
            <source>Real-time clock: CDT runs on from PDT while IN is TRUE.</source>
            <translation>实时时钟：IN 为 TRUE 时 CDT 从 PDT 开始走时。</translation>
        </message>
        <message>
            <source>On a rising edge of TRIG, writes MSG to the messages pane.</source>
            <translation>在 TRIG 的上升沿把 MSG 写入消息窗格。</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::StringPage</name>
        <message>
            <source>Characters:</source>
            <translation>字符：</translation>
        </message>
        <message>
            <source>Length (optional):</source>
            <translation>长度(可选)：</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::StructPage</name>
        <message>
            <source>Name</source>
            <translation>名称</translation>
        </message>
        <message>
            <source>Type</source>
            <translation>类型</translation>
        </message>
        <message>
            <source>Initial value</source>
            <translation>初始值</translation>
        </message>
        <message>
            <source>Comment</source>
            <translation>注释</translation>
        </message>
        <message>
            <source>Members</source>
            <translation>成员</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::SubrangePage</name>
        <message>
            <source>Base type:</source>
            <translation>基本类型：</translation>
        </message>
        <message>
            <source>Low:</source>
            <translation>下限：</translation>
        </message>
        <message>
            <source>High:</source>
            <translation>上限：</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::TaskRows</name>
        <message>
            <source>"%1" is not a time such as T#10ms, T#1s or 20ms.</source>
            <translation>"%1" 不是有效的时间，例如 T#10ms、T#1s 或 20ms。</translation>
        </message>
        <message>
            <source>Enter a name.</source>
            <translation>请输入名称。</translation>
        </message>
        <message>
            <source>"%1" is not a valid name: use letters, digits and single underscores.</source>
            <translation>"%1" 不是有效的名称：请使用字母、数字和单个下划线。</translation>
        </message>
        <message>
            <source>A cyclic task needs an interval above 0; leave it empty for a task started by its SINGLE variable.</source>
            <translation>循环任务的间隔必须大于 0；由 SINGLE 变量启动的任务请将间隔留空。</translation>
        </message>
        <message>
            <source>There is no global BOOL variable %1 in this configuration.</source>
            <translation>此配置中没有全局 BOOL 变量 %1。</translation>
        </message>
        <message>
            <source>A task runs either every interval or when its SINGLE variable becomes TRUE: clear the interval or the SINGLE variable.</source>
            <translation>任务要么按间隔执行，要么在其 SINGLE 变量变为 TRUE 时执行：请清除间隔或 SINGLE 变量。</translation>
        </message>
        <message>
            <source>A watchdog time must be above 0; leave it empty for none.</source>
            <translation>看门狗时间必须大于 0；留空表示不设置。</translation>
        </message>
        <message>
            <source>"%1" is not a priority: use a whole number from 0 (highest) to 65535.</source>
            <translation>"%1" 不是有效的优先级：请使用 0（最高）到 65535 之间的整数。</translation>
        </message>
        <message>
            <source>There is another resource named %1.</source>
            <translation>已有名为 %1 的资源。</translation>
        </message>
        <message>
            <source>There is another task named %1.</source>
            <translation>已有名为 %1 的任务。</translation>
        </message>
        <message>
            <source>There is another program instance named %1.</source>
            <translation>已有名为 %1 的程序实例。</translation>
        </message>
        <message>
            <source>There is no program called %1.</source>
            <translation>没有名为 %1 的程序。</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::TextEditorWidget</name>
        <message>
            <source>Online: %1, cycle %2</source>
            <translation>在线:%1,周期 %2</translation>
        </message>
        <message>
            <source>no instance</source>
            <translation>无实例</translation>
        </message>
        <message>
            <source>&amp;Operator...</source>
            <translation>运算符(&amp;O)...</translation>
        </message>
        <message>
            <source>O&amp;perand...</source>
            <translation>操作数(&amp;P)...</translation>
        </message>
        <message>
            <source>&amp;Function...</source>
            <translation>函数(&amp;F)...</translation>
        </message>
        <message>
            <source>Function &amp;Block...</source>
            <translation>功能块(&amp;B)...</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::cfc</name>
        <message>
            <source>There is nothing to paste.</source>
            <translation>没有可粘贴的内容。</translation>
        </message>
        <message>
            <source>Select the elements to delete first.</source>
            <translation>请先选择要删除的元素。</translation>
        </message>
        <message>
            <source>Select the elements to move first.</source>
            <translation>请先选择要移动的元素。</translation>
        </message>
        <message>
            <source>The wire has no element at one of its ends.</source>
            <translation>连线的一端没有元素。</translation>
        </message>
        <message>
            <source>That element has no such output.</source>
            <translation>该元素没有这个输出。</translation>
        </message>
        <message>
            <source>That element has no such input.</source>
            <translation>该元素没有这个输入。</translation>
        </message>
        <message>
            <source>Select an element that has an execution order number (a box, an output, a jump, a return or a label).</source>
            <translation>请选择一个有执行顺序号的元素(功能块、输出、跳转、返回或标号)。</translation>
        </message>
        <message>
            <source>Only boxes, outputs, jumps, returns and labels have an execution order number.</source>
            <translation>只有功能块、输出、跳转、返回和标号才有执行顺序号。</translation>
        </message>
        <message>
            <source>The number must lie between 1 and %1.</source>
            <translation>序号必须在 1 到 %1 之间。</translation>
        </message>
        <message>
            <source>The box is gone.</source>
            <translation>该功能块已不存在。</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::cfc::CfcEditor</name>
        <message>
            <source>This CFC diagram cannot be shown: %1</source>
            <translation>无法显示此 CFC 图:%1</translation>
        </message>
        <message>
            <source>Move</source>
            <translation>移动</translation>
        </message>
        <message>
            <source>Connect</source>
            <translation>连线</translation>
        </message>
        <message>
            <source>Insert %1</source>
            <translation>插入 %1</translation>
        </message>
        <message>
            <source>Insert input</source>
            <translation>插入输入</translation>
        </message>
        <message>
            <source>Insert output</source>
            <translation>插入输出</translation>
        </message>
        <message>
            <source>Insert jump</source>
            <translation>插入跳转</translation>
        </message>
        <message>
            <source>Insert label</source>
            <translation>插入标号</translation>
        </message>
        <message>
            <source>Insert return</source>
            <translation>插入返回</translation>
        </message>
        <message>
            <source>Insert comment</source>
            <translation>插入注释</translation>
        </message>
        <message>
            <source>Insert connection mark</source>
            <translation>插入连接标记</translation>
        </message>
        <message>
            <source>Rename</source>
            <translation>重命名</translation>
        </message>
        <message>
            <source>The element is gone.</source>
            <translation>该元素已不存在。</translation>
        </message>
        <message>
            <source>Change box to %1</source>
            <translation>将功能块改为 %1</translation>
        </message>
        <message>
            <source>Negate</source>
            <translation>取反</translation>
        </message>
        <message>
            <source>Select an input or an output to negate.</source>
            <translation>请选择要取反的输入或输出。</translation>
        </message>
        <message>
            <source>Delete</source>
            <translation>删除</translation>
        </message>
        <message>
            <source>Select the elements to copy first.</source>
            <translation>请先选择要复制的元素。</translation>
        </message>
        <message>
            <source>Paste</source>
            <translation>粘贴</translation>
        </message>
        <message>
            <source>Order by data flow</source>
            <translation>按数据流排序</translation>
        </message>
        <message>
            <source>Order by topology</source>
            <translation>按拓扑排序</translation>
        </message>
        <message>
            <source>Change execution order</source>
            <translation>更改执行顺序</translation>
        </message>
        <message>
            <source>Set execution order</source>
            <translation>设置执行顺序</translation>
        </message>
        <message>
            <source>Select one element that has an execution order number.</source>
            <translation>请只选择一个有执行顺序号的元素。</translation>
        </message>
        <message>
            <source>Execution Order</source>
            <translation>执行顺序</translation>
        </message>
        <message>
            <source>Number of this element (1 to %1):</source>
            <translation>此元素的序号(1 到 %1):</translation>
        </message>
        <message>
            <source>Insert Comment</source>
            <translation>插入注释</translation>
        </message>
        <message>
            <source>Comment:</source>
            <translation>注释:</translation>
        </message>
        <message>
            <source>&amp;Box</source>
            <translation>功能块(&amp;B)</translation>
        </message>
        <message>
            <source>Box</source>
            <translation>功能块</translation>
        </message>
        <message>
            <source>&amp;Input</source>
            <translation>输入(&amp;I)</translation>
        </message>
        <message>
            <source>Input</source>
            <translation>输入</translation>
        </message>
        <message>
            <source>O&amp;utput</source>
            <translation>输出(&amp;U)</translation>
        </message>
        <message>
            <source>Output</source>
            <translation>输出</translation>
        </message>
        <message>
            <source>&amp;Jump</source>
            <translation>跳转(&amp;J)</translation>
        </message>
        <message>
            <source>&amp;Label</source>
            <translation>标号(&amp;L)</translation>
        </message>
        <message>
            <source>&amp;Return</source>
            <translation>返回(&amp;R)</translation>
        </message>
        <message>
            <source>Co&amp;mment…</source>
            <translation>注释(&amp;M)…</translation>
        </message>
        <message>
            <source>Connection Mark (&amp;Source)</source>
            <translation>连接标记 - 源(&amp;S)</translation>
        </message>
        <message>
            <source>Connection Mark (&amp;Sink)</source>
            <translation>连接标记 - 目标(&amp;K)</translation>
        </message>
        <message>
            <source>Ne&amp;gate</source>
            <translation>取反(&amp;G)</translation>
        </message>
        <message>
            <source>Edit &amp;Name</source>
            <translation>编辑名称(&amp;N)</translation>
        </message>
        <message>
            <source>Order by &amp;Data Flow</source>
            <translation>按数据流排序(&amp;D)</translation>
        </message>
        <message>
            <source>Data Flow</source>
            <translation>数据流</translation>
        </message>
        <message>
            <source>Order by &amp;Topology</source>
            <translation>按拓扑排序(&amp;T)</translation>
        </message>
        <message>
            <source>Order: One &amp;Earlier</source>
            <translation>顺序:提前一位(&amp;E)</translation>
        </message>
        <message>
            <source>Order: One &amp;Later</source>
            <translation>顺序:推后一位(&amp;L)</translation>
        </message>
        <message>
            <source>Order: To the &amp;Front</source>
            <translation>顺序:移到最前(&amp;F)</translation>
        </message>
        <message>
            <source>Order: To the &amp;Back</source>
            <translation>顺序:移到最后(&amp;B)</translation>
        </message>
        <message>
            <source>Set Order &amp;Number…</source>
            <translation>设置顺序号(&amp;N)…</translation>
        </message>
        <message>
            <source>Cu&amp;t</source>
            <translation>剪切(&amp;T)</translation>
        </message>
        <message>
            <source>&amp;Copy</source>
            <translation>复制(&amp;C)</translation>
        </message>
        <message>
            <source>&amp;Paste</source>
            <translation>粘贴(&amp;P)</translation>
        </message>
        <message>
            <source>&amp;Delete</source>
            <translation>删除(&amp;D)</translation>
        </message>
        <message>
            <source>Jump</source>
            <translation>跳转</translation>
        </message>
        <message>
            <source>Label</source>
            <translation>标号</translation>
        </message>
        <message>
            <source>Return</source>
            <translation>返回</translation>
        </message>
        <message>
            <source>Comment</source>
            <translation>注释</translation>
        </message>
        <message>
            <source>Select a box to give it EN/ENO or take them away.</source>
            <translation>请选择一个功能块,为其添加或去掉 EN/ENO。</translation>
        </message>
        <message>
            <source>Remove EN/ENO from %1</source>
            <translation>去掉 %1 的 EN/ENO</translation>
        </message>
        <message>
            <source>Add EN/ENO to %1</source>
            <translation>为 %1 添加 EN/ENO</translation>
        </message>
        <message>
            <source>EN/ENO</source>
            <translation>EN/ENO</translation>
        </message>
        <message>
            <source>box %1 (%2)</source>
            <translation>功能块 %1（%2）</translation>
        </message>
        <message>
            <source>element %1</source>
            <translation>元素 %1</translation>
        </message>
        <message>
            <source>output %1 (%2)</source>
            <translation>输出 %1（%2）</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::fbd::FbdEditor</name>
        <message>
            <source>Insert network</source>
            <translation>插入节</translation>
        </message>
        <message>
            <source>Insert %1</source>
            <translation>插入 %1</translation>
        </message>
        <message>
            <source>Change box to %1</source>
            <translation>将方块改为 %1</translation>
        </message>
        <message>
            <source>Insert input</source>
            <translation>插入输入</translation>
        </message>
        <message>
            <source>Insert output</source>
            <translation>插入输出</translation>
        </message>
        <message>
            <source>Insert assignment</source>
            <translation>插入赋值</translation>
        </message>
        <message>
            <source>Insert jump</source>
            <translation>插入跳转</translation>
        </message>
        <message>
            <source>Insert return</source>
            <translation>插入返回</translation>
        </message>
        <message>
            <source>Change label</source>
            <translation>修改标号</translation>
        </message>
        <message>
            <source>Change comment</source>
            <translation>修改注释</translation>
        </message>
        <message>
            <source>Negate</source>
            <translation>反向</translation>
        </message>
        <message>
            <source>Set/Reset</source>
            <translation>置位/复位</translation>
        </message>
        <message>
            <source>Edge</source>
            <translation>边沿</translation>
        </message>
        <message>
            <source>Rename</source>
            <translation>重命名</translation>
        </message>
        <message>
            <source>Delete</source>
            <translation>删除</translation>
        </message>
        <message>
            <source>Paste</source>
            <translation>粘贴</translation>
        </message>
        <message>
            <source>&amp;Network Before</source>
            <translation>前节(&amp;N)</translation>
        </message>
        <message>
            <source>Network Aft&amp;er</source>
            <translation>后节(&amp;E)</translation>
        </message>
        <message>
            <source>Network</source>
            <translation>节</translation>
        </message>
        <message>
            <source>&amp;Operator</source>
            <translation>运算符(&amp;O)</translation>
        </message>
        <message>
            <source>Operator</source>
            <translation>运算符</translation>
        </message>
        <message>
            <source>Box with E&amp;N…</source>
            <translation>使能运算符(&amp;N)</translation>
        </message>
        <message>
            <source>&amp;Input</source>
            <translation>输入(&amp;I)</translation>
        </message>
        <message>
            <source>O&amp;utput</source>
            <translation>输出(&amp;U)</translation>
        </message>
        <message>
            <source>&amp;Assignment</source>
            <translation>赋值(&amp;A)</translation>
        </message>
        <message>
            <source>&amp;Jump…</source>
            <translation>跳转(&amp;J)…</translation>
        </message>
        <message>
            <source>&amp;Return</source>
            <translation>返回(&amp;R)</translation>
        </message>
        <message>
            <source>La&amp;bel…</source>
            <translation>标号(&amp;B)…</translation>
        </message>
        <message>
            <source>Co&amp;mment…</source>
            <translation>注释(&amp;M)…</translation>
        </message>
        <message>
            <source>Ne&amp;gate</source>
            <translation>反向(&amp;G)</translation>
        </message>
        <message>
            <source>&amp;Set/Reset</source>
            <translation>置位/复位(&amp;S)</translation>
        </message>
        <message>
            <source>S/R</source>
            <translation>S/R</translation>
        </message>
        <message>
            <source>E&amp;dge (Rising/Falling)</source>
            <translation>边沿(上升/下降)(&amp;D)</translation>
        </message>
        <message>
            <source>Edit &amp;Name</source>
            <translation>编辑名称(&amp;N)</translation>
        </message>
        <message>
            <source>Cu&amp;t</source>
            <translation>剪切(&amp;T)</translation>
        </message>
        <message>
            <source>&amp;Copy</source>
            <translation>复制(&amp;C)</translation>
        </message>
        <message>
            <source>&amp;Paste</source>
            <translation>粘贴(&amp;P)</translation>
        </message>
        <message>
            <source>&amp;Delete</source>
            <translation>删除(&amp;D)</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::fbd::FbdEdits</name>
        <message>
            <source>Insert a network first (Network After, Ctrl+T).</source>
            <translation>请先插入一个节(后节,Ctrl+T)。</translation>
        </message>
        <message>
            <source>This network was drawn freely in another tool: it is not a tree of boxes, so boxes, inputs and outputs cannot be inserted into it. Its elements can still be renamed, negated or deleted.</source>
            <translation>此节是在其他工具中自由绘制的:它不是由方块组成的树,因此不能插入方块、输入或输出。其元素仍可重命名、反向或删除。</translation>
        </message>
        <message>
            <source>Nothing is wired to this input yet.</source>
            <translation>此输入尚未连接任何内容。</translation>
        </message>
        <message>
            <source>Nothing is wired to this element yet.</source>
            <translation>此元素尚未连接任何内容。</translation>
        </message>
        <message>
            <source>This box has no output.</source>
            <translation>此方块没有输出。</translation>
        </message>
        <message>
            <source>The last box of this network has no output.</source>
            <translation>此节的最后一个方块没有输出。</translation>
        </message>
        <message>
            <source>Select a box or one of its inputs first.</source>
            <translation>请先选择一个方块或它的一个输入。</translation>
        </message>
        <message>
            <source>%1 has a fixed number of inputs.</source>
            <translation>%1 的输入数量是固定的。</translation>
        </message>
        <message>
            <source>Select a box first.</source>
            <translation>请先选择一个方块。</translation>
        </message>
        <message>
            <source>%1 has no output to feed the input with.</source>
            <translation>%1 没有可以连接到该输入的输出。</translation>
        </message>
        <message>
            <source>%1 has no output to feed the assignment with.</source>
            <translation>%1 没有可用于赋值的输出。</translation>
        </message>
        <message>
            <source>%1 has no output to pass the value on.</source>
            <translation>%1 没有可以传递数值的输出。</translation>
        </message>
        <message>
            <source>Select an input, an output, an assignment, a jump or a return first.</source>
            <translation>请先选择一个输入、输出、赋值、跳转或返回。</translation>
        </message>
        <message>
            <source>The value in front of this jump or return goes elsewhere too: negate the output that feeds it, or insert a NOT.</source>
            <translation>此跳转或返回前面的值也用于其他地方:请对提供该值的输出取反,或插入一个 NOT。</translation>
        </message>
        <message>
            <source>Select an assignment (an output variable) first.</source>
            <translation>请先选择一个赋值(输出变量)。</translation>
        </message>
        <message>
            <source>Select an input of a box first (edge detection works on BOOL inputs).</source>
            <translation>请先选择方块的一个输入(边沿检测作用于 BOOL 输入)。</translation>
        </message>
        <message>
            <source>There is no such element.</source>
            <translation>没有这个元素。</translation>
        </message>
        <message>
            <source>Type a name or a value.</source>
            <translation>请输入名称或数值。</translation>
        </message>
        <message>
            <source>This element has no name to type.</source>
            <translation>此元素没有可输入的名称。</translation>
        </message>
        <message>
            <source>Select an element of the network first.</source>
            <translation>请先选择节中的一个元素。</translation>
        </message>
        <message>
            <source>There is no assignment on this output to delete.</source>
            <translation>此输出上没有可删除的赋值。</translation>
        </message>
        <message>
            <source>Select an input of a box first.</source>
            <translation>请先选择方块的一个输入。</translation>
        </message>
        <message>
            <source>Select what to delete first: an element, an input, an output or a network.</source>
            <translation>请先选择要删除的内容:元素、输入、输出或节。</translation>
        </message>
        <message>
            <source>There is nothing to copy here.</source>
            <translation>这里没有可复制的内容。</translation>
        </message>
        <message>
            <source>Select a network, a box or an input to copy.</source>
            <translation>请选择要复制的节、方块或输入。</translation>
        </message>
        <message>
            <source>There is nothing to paste.</source>
            <translation>没有可粘贴的内容。</translation>
        </message>
        <message>
            <source>The clipboard holds elements of another language (not a function block diagram): nothing was pasted.</source>
            <translation>剪贴板中是其他语言的元素(不是功能块图):未粘贴任何内容。</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::ld::LdEditor</name>
        <message>
            <source>free</source>
            <translation>自由</translation>
        </message>
        <message>
            <source>Insert network</source>
            <translation>插入节</translation>
        </message>
        <message>
            <source>Insert contact</source>
            <translation>插入触点</translation>
        </message>
        <message>
            <source>Insert parallel contact</source>
            <translation>插入并联触点</translation>
        </message>
        <message>
            <source>Insert coil</source>
            <translation>插入线圈</translation>
        </message>
        <message>
            <source>Insert box %1</source>
            <translation>插入功能块 %1</translation>
        </message>
        <message>
            <source>Insert jump</source>
            <translation>插入跳转</translation>
        </message>
        <message>
            <source>Insert return</source>
            <translation>插入返回</translation>
        </message>
        <message>
            <source>Insert input</source>
            <translation>插入输入</translation>
        </message>
        <message>
            <source>Insert assignment</source>
            <translation>插入赋值</translation>
        </message>
        <message>
            <source>Insert operator</source>
            <translation>插入运算符</translation>
        </message>
        <message>
            <source>Change label</source>
            <translation>修改标号</translation>
        </message>
        <message>
            <source>Change comment</source>
            <translation>修改注释</translation>
        </message>
        <message>
            <source>Negate</source>
            <translation>取反</translation>
        </message>
        <message>
            <source>Set/Reset</source>
            <translation>置位/复位</translation>
        </message>
        <message>
            <source>Edge</source>
            <translation>边沿</translation>
        </message>
        <message>
            <source>Rename</source>
            <translation>重命名</translation>
        </message>
        <message>
            <source>Delete</source>
            <translation>删除</translation>
        </message>
        <message>
            <source>Paste</source>
            <translation>粘贴</translation>
        </message>
        <message>
            <source>&amp;Network Before</source>
            <translation>前节(&amp;N)</translation>
        </message>
        <message>
            <source>Network Aft&amp;er</source>
            <translation>后节(&amp;E)</translation>
        </message>
        <message>
            <source>C&amp;ontact</source>
            <translation>串联(&amp;O)</translation>
        </message>
        <message>
            <source>&amp;Parallel Contact (Below)</source>
            <translation>并联触点(&amp;P)</translation>
        </message>
        <message>
            <source>Parallel Contact (Abo&amp;ve)</source>
            <translation>并联触点(上方)(&amp;V)</translation>
        </message>
        <message>
            <source>&amp;Function Block…</source>
            <translation>功能块(&amp;F)…</translation>
        </message>
        <message>
            <source>Coi&amp;l</source>
            <translation>线圈(&amp;L)</translation>
        </message>
        <message>
            <source>Box with E&amp;N…</source>
            <translation>使能运算符(&amp;E)…</translation>
        </message>
        <message>
            <source>Insert at Box: In&amp;put</source>
            <translation>插入选项(&amp;K): 输入</translation>
        </message>
        <message>
            <source>Insert at Box: &amp;Assignment</source>
            <translation>插入选项: 赋值(&amp;A)</translation>
        </message>
        <message>
            <source>Insert at Box: Operato&amp;r</source>
            <translation>插入选项: 运算符(&amp;Y)</translation>
        </message>
        <message>
            <source>&amp;Jump…</source>
            <translation>跳转(&amp;J)…</translation>
        </message>
        <message>
            <source>&amp;Return</source>
            <translation>返回(&amp;R)</translation>
        </message>
        <message>
            <source>La&amp;bel…</source>
            <translation>标号(&amp;B)…</translation>
        </message>
        <message>
            <source>Co&amp;mment…</source>
            <translation>注释(&amp;C)…</translation>
        </message>
        <message>
            <source>Ne&amp;gate</source>
            <translation>取反(&amp;G)</translation>
        </message>
        <message>
            <source>&amp;Set/Reset</source>
            <translation>置位/复位(&amp;S)</translation>
        </message>
        <message>
            <source>E&amp;dge (P/N)</source>
            <translation>边沿 (P/N)(&amp;D)</translation>
        </message>
        <message>
            <source>Edit &amp;Name</source>
            <translation>编辑名称(&amp;M)</translation>
        </message>
        <message>
            <source>Cu&amp;t</source>
            <translation>剪切(&amp;T)</translation>
        </message>
        <message>
            <source>&amp;Copy</source>
            <translation>复制(&amp;C)</translation>
        </message>
        <message>
            <source>&amp;Paste</source>
            <translation>粘贴(&amp;P)</translation>
        </message>
        <message>
            <source>Paste &amp;Below</source>
            <translation>粘贴到下方(&amp;B)</translation>
        </message>
        <message>
            <source>Paste Abo&amp;ve</source>
            <translation>粘贴到上方(&amp;V)</translation>
        </message>
        <message>
            <source>&amp;Delete</source>
            <translation>删除(&amp;D)</translation>
        </message>
        <message>
            <source>Network</source>
            <translation>节</translation>
        </message>
        <message>
            <source>Parallel</source>
            <translation>并联</translation>
        </message>
        <message>
            <source>Box…</source>
            <translation>功能块…</translation>
        </message>
        <message>
            <source>S/R</source>
            <translation>S/R</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::ld::LdEdits</name>
        <message>
            <source>There is no network here. Insert a network first (Network After).</source>
            <translation>这里没有节。请先插入一个节(后节)。</translation>
        </message>
        <message>
            <source>This network is drawn freely by another tool, not as a rung: change its elements one by one (their names, negation), or delete it and draw it again.</source>
            <translation>此节由其他工具自由绘制,不是梯级: 可以逐个修改其元素(名称、取反),或删除后重新绘制。</translation>
        </message>
        <message>
            <source>Put the cursor on an element or on a wire of the rung first.</source>
            <translation>请先把光标放在梯级的元素或连线上。</translation>
        </message>
        <message>
            <source>Network %1 has the label %2 already: labels name one network each.</source>
            <translation>第 %1 节已有标号 %2: 每个标号只能用于一个节。</translation>
        </message>
        <message>
            <source>Select the contacts (shift-click for a range) that the parallel contact goes around.</source>
            <translation>请选择并联触点要并联的触点(按住 Shift 单击可选择一段)。</translation>
        </message>
        <message>
            <source>A parallel contact goes around contacts and boxes; for another output use Coil.</source>
            <translation>并联触点只能并联在触点和功能块周围;要增加输出请用“线圈”。</translation>
        </message>
        <message>
            <source>Choose the function or function block the box calls.</source>
            <translation>请选择功能块框调用的函数或功能块。</translation>
        </message>
        <message>
            <source>This box has no input the rung could drive: use the box with EN.</source>
            <translation>此功能块没有可由梯级驱动的输入: 请使用带使能端的功能块。</translation>
        </message>
        <message>
            <source>Select a box (or a variable on its inputs) first.</source>
            <translation>请先选择一个功能块(或其输入上的变量)。</translation>
        </message>
        <message>
            <source>%1 has a fixed number of inputs.</source>
            <translation>%1 的输入个数是固定的。</translation>
        </message>
        <message>
            <source>Select a box first.</source>
            <translation>请先选择一个功能块。</translation>
        </message>
        <message>
            <source>Every output of this box has an assignment already.</source>
            <translation>此功能块的每个输出都已有赋值。</translation>
        </message>
        <message>
            <source>Select a variable on a box's input first: the operator goes in front of it.</source>
            <translation>请先选择功能块输入上的变量: 运算符插在它前面。</translation>
        </message>
        <message>
            <source>An operator needs an input and an output.</source>
            <translation>运算符需要一个输入和一个输出。</translation>
        </message>
        <message>
            <source>Select a contact or a coil to negate.</source>
            <translation>请选择要取反的触点或线圈。</translation>
        </message>
        <message>
            <source>Select a coil: Set/Reset makes it a set (S) or reset (R) coil.</source>
            <translation>请选择一个线圈: 置位/复位把它变成置位(S)或复位(R)线圈。</translation>
        </message>
        <message>
            <source>Select a contact or a coil: an edge makes it react to a rising (P) or falling (N) edge.</source>
            <translation>请选择触点或线圈: 边沿使其响应上升沿(P)或下降沿(N)。</translation>
        </message>
        <message>
            <source>The element is gone.</source>
            <translation>该元素已不存在。</translation>
        </message>
        <message>
            <source>Type a name (or press Esc to keep the old one).</source>
            <translation>请输入名称(或按 Esc 保留原名)。</translation>
        </message>
        <message>
            <source>This element has no name to type.</source>
            <translation>此元素没有可输入的名称。</translation>
        </message>
        <message>
            <source>Select an element or a network to delete.</source>
            <translation>请选择要删除的元素或节。</translation>
        </message>
        <message>
            <source>The power rails belong to the network: delete the network to remove them.</source>
            <translation>能量线属于节: 删除节才能删除它们。</translation>
        </message>
        <message>
            <source>The clipboard holds elements that do not form a rung.</source>
            <translation>剪贴板中的元素不构成梯级。</translation>
        </message>
        <message>
            <source>This network is drawn freely by another tool, not as a rung: paste into a rung network.</source>
            <translation>此节由其他工具自由绘制,不是梯级: 请粘贴到梯级节中。</translation>
        </message>
        <message>
            <source>Select the elements the pasted ones go parallel to.</source>
            <translation>请选择要与粘贴内容并联的元素。</translation>
        </message>
        <message>
            <source>There is nothing to copy here.</source>
            <translation>这里没有可复制的内容。</translation>
        </message>
        <message>
            <source>Select elements or a network to copy.</source>
            <translation>请选择要复制的元素或节。</translation>
        </message>
        <message>
            <source>This network is drawn freely: copy the whole network (click its number).</source>
            <translation>此节是自由绘制的: 请复制整个节(单击节号)。</translation>
        </message>
        <message>
            <source>Select rung elements (contacts, coils, boxes) or a network to copy.</source>
            <translation>请选择要复制的梯级元素(触点、线圈、功能块)或节。</translation>
        </message>
        <message>
            <source>There is nothing to paste.</source>
            <translation>没有可粘贴的内容。</translation>
        </message>
        <message>
            <source>The clipboard holds elements of another language (not a ladder diagram): nothing was pasted.</source>
            <translation>剪贴板中是其他语言的元素(不是梯形图): 未粘贴任何内容。</translation>
        </message>
        <message>
            <source>%1 is a program: a box calls a function or a function block.</source>
            <translation>%1 是程序: 功能块框只能调用函数或功能块。</translation>
        </message>
        <message>
            <source>There is no function or function block called %1 (in the standard library or the project).</source>
            <translation>没有名为 %1 的函数或功能块(标准库和项目中都没有)。</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::sfc::ActionAssociationsDialog</name>
        <message>
            <source>IEC Actions of the Step</source>
            <translation>步的 IEC 动作</translation>
        </message>
        <message>
            <source>Qualifier</source>
            <translation>限定符</translation>
        </message>
        <message>
            <source>Time</source>
            <translation>时间</translation>
        </message>
        <message>
            <source>Action or variable</source>
            <translation>动作或变量</translation>
        </message>
        <message>
            <source>Indicator</source>
            <translation>指示变量</translation>
        </message>
        <message>
            <source>Add</source>
            <translation>添加</translation>
        </message>
        <message>
            <source>Remove</source>
            <translation>移除</translation>
        </message>
        <message>
            <source>Move Up</source>
            <translation>上移</translation>
        </message>
        <message>
            <source>Move Down</source>
            <translation>下移</translation>
        </message>
        <message>
            <source>BOOL variable</source>
            <translation>BOOL 变量</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::sfc::SfcEditor</name>
        <message>
            <source>Step-Transition (after)</source>
            <translation>步-转换(之后)</translation>
        </message>
        <message>
            <source>Step-Transition (before)</source>
            <translation>步-转换(之前)</translation>
        </message>
        <message>
            <source>Alternative Branch (right)</source>
            <translation>选择分支(右)</translation>
        </message>
        <message>
            <source>Alternative Branch (left)</source>
            <translation>选择分支(左)</translation>
        </message>
        <message>
            <source>Parallel Branch (right)</source>
            <translation>并行分支(右)</translation>
        </message>
        <message>
            <source>Parallel Branch (left)</source>
            <translation>并行分支(左)</translation>
        </message>
        <message>
            <source>Jump…</source>
            <translation>跳转…</translation>
        </message>
        <message>
            <source>Transition-Jump…</source>
            <translation>转换-跳转…</translation>
        </message>
        <message>
            <source>Macro Step</source>
            <translation>宏步</translation>
        </message>
        <message>
            <source>Delete</source>
            <translation>删除</translation>
        </message>
        <message>
            <source>Cut</source>
            <translation>剪切</translation>
        </message>
        <message>
            <source>Copy</source>
            <translation>复制</translation>
        </message>
        <message>
            <source>Paste</source>
            <translation>粘贴</translation>
        </message>
        <message>
            <source>Step Properties…</source>
            <translation>步属性…</translation>
        </message>
        <message>
            <source>Select a step first.</source>
            <translation>请先选择一个步。</translation>
        </message>
        <message>
            <source>IEC Actions…</source>
            <translation>IEC 动作…</translation>
        </message>
        <message>
            <source>Edit Condition</source>
            <translation>编辑转换条件</translation>
        </message>
        <message>
            <source>Select a transition first.</source>
            <translation>请先选择一个转换。</translation>
        </message>
        <message>
            <source>Transition Priority…</source>
            <translation>转换优先级…</translation>
        </message>
        <message>
            <source>Transition Priority</source>
            <translation>转换优先级</translation>
        </message>
        <message>
            <source>Priority (0: none, branches are tried from left to right):</source>
            <translation>优先级(0:无,分支从左到右依次判断):</translation>
        </message>
        <message>
            <source>Leave Macro</source>
            <translation>退出宏</translation>
        </message>
        <message>
            <source>New chart</source>
            <translation>新建顺序功能图</translation>
        </message>
        <message>
            <source>Insert step-transition</source>
            <translation>插入步-转换</translation>
        </message>
        <message>
            <source>Insert alternative branch</source>
            <translation>插入选择分支</translation>
        </message>
        <message>
            <source>Insert parallel branch</source>
            <translation>插入并行分支</translation>
        </message>
        <message>
            <source>Insert jump</source>
            <translation>插入跳转</translation>
        </message>
        <message>
            <source>Insert transition-jump</source>
            <translation>插入转换-跳转</translation>
        </message>
        <message>
            <source>Insert macro step</source>
            <translation>插入宏步</translation>
        </message>
        <message>
            <source>Change step</source>
            <translation>修改步</translation>
        </message>
        <message>
            <source>Change condition</source>
            <translation>修改转换条件</translation>
        </message>
        <message>
            <source>Change priority</source>
            <translation>修改优先级</translation>
        </message>
        <message>
            <source>Add %1 action %2</source>
            <translation>添加%1动作 %2</translation>
        </message>
        <message>
            <source>Select a macro step first.</source>
            <translation>请先选择一个宏步。</translation>
        </message>
        <message>
            <source>Inside macro step %1</source>
            <translation>宏步 %1 内部</translation>
        </message>
        <message>
            <source>An ST expression, or the name of a transition of the POU. Enter applies, Esc cancels.</source>
            <translation>ST 表达式,或该 POU 中某个转换的名称。回车确认,Esc 取消。</translation>
        </message>
        <message>
            <source>Change actions</source>
            <translation>修改动作</translation>
        </message>
        <message>
            <source>The chart has no step to jump to.</source>
            <translation>顺序功能图中没有可跳转的步。</translation>
        </message>
        <message>
            <source>Jump</source>
            <translation>跳转</translation>
        </message>
        <message>
            <source>Jump to step:</source>
            <translation>跳转到步:</translation>
        </message>
        <message>
            <source>Arrange Chart</source>
            <translation>整理图表</translation>
        </message>
        <message>
            <source>The chart is empty: there is nothing to arrange.</source>
            <translation>图表为空：没有可整理的内容。</translation>
        </message>
        <message>
            <source>Arrange chart</source>
            <translation>整理图表</translation>
        </message>
        <message>
            <source>Initial Step</source>
            <translation>初始步</translation>
        </message>
        <message>
            <source>Step</source>
            <translation>步</translation>
        </message>
        <message>
            <source>Alternative</source>
            <translation>选择分支</translation>
        </message>
        <message>
            <source>Parallel</source>
            <translation>并行</translation>
        </message>
        <message>
            <source>Macro</source>
            <translation>宏步</translation>
        </message>
        <message>
            <source>Properties…</source>
            <translation>属性…</translation>
        </message>
        <message>
            <source>Actions…</source>
            <translation>动作…</translation>
        </message>
        <message>
            <source>Arrange</source>
            <translation>整理</translation>
        </message>
        <message>
            <source>Leave</source>
            <translation>退出宏</translation>
        </message>
        <message>
            <source>step %1</source>
            <translation>步 %1</translation>
        </message>
        <message>
            <source>a transition</source>
            <translation>一个转换</translation>
        </message>
        <message>
            <source>the transition after %1</source>
            <translation>%1 之后的转换</translation>
        </message>
        <message>
            <source>an action block</source>
            <translation>一个动作块</translation>
        </message>
        <message>
            <source>the actions of %1</source>
            <translation>%1 的动作</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::sfc::SfcEdits</name>
        <message>
            <source>Select a step or a transition first.</source>
            <translation>请先选择一个步或转换。</translation>
        </message>
        <message>
            <source>Nothing can follow a jump. Select the transition before it.</source>
            <translation>跳转之后不能再有元素。请选择跳转前面的转换。</translation>
        </message>
        <message>
            <source>Nothing can go before the initial step. Insert after it instead.</source>
            <translation>初始步之前不能插入元素。请在其后插入。</translation>
        </message>
        <message>
            <source>Select a step (or steps from one to another) to add a parallel branch.</source>
            <translation>请选择一个步(或从一个步到另一个步的范围)以添加并行分支。</translation>
        </message>
        <message>
            <source>Select a transition (or a range from a transition to a transition) to add an alternative branch.</source>
            <translation>请选择一个转换(或从一个转换到另一个转换的范围)以添加选择分支。</translation>
        </message>
        <message>
            <source>The chart is not empty.</source>
            <translation>顺序功能图不为空。</translation>
        </message>
        <message>
            <source>There is no step '%1' to jump to.</source>
            <translation>没有可跳转的步 '%1'。</translation>
        </message>
        <message>
            <source>Select the transition the jump follows.</source>
            <translation>请选择跳转之前的转换。</translation>
        </message>
        <message>
            <source>A jump can only follow the last transition of a chain or branch.</source>
            <translation>跳转只能位于链或分支的最后一个转换之后。</translation>
        </message>
        <message>
            <source>Select the step the transition and jump follow.</source>
            <translation>请选择转换和跳转之前的步。</translation>
        </message>
        <message>
            <source>A transition-jump can only follow the last step of a chain or of an alternative branch.</source>
            <translation>转换-跳转只能位于链或选择分支的最后一个步之后。</translation>
        </message>
        <message>
            <source>Select what to delete first.</source>
            <translation>请先选择要删除的内容。</translation>
        </message>
        <message>
            <source>The initial step cannot be deleted on its own. Delete what follows it, or the whole chart.</source>
            <translation>初始步不能单独删除。请删除其后的内容,或删除整个顺序功能图。</translation>
        </message>
        <message>
            <source>Deleting this would leave two steps or two transitions in a row. Select a step together with its transition.</source>
            <translation>删除后会出现两个相连的步或两个相连的转换。请同时选择步及其转换。</translation>
        </message>
        <message>
            <source>Select a step first.</source>
            <translation>请先选择一个步。</translation>
        </message>
        <message>
            <source>'%1' is not a valid step name: use letters, digits and single underscores, starting with a letter.</source>
            <translation>'%1' 不是有效的步名称:请使用字母、数字和单个下划线,并以字母开头。</translation>
        </message>
        <message>
            <source>There is already a step named '%1'.</source>
            <translation>已存在名为 '%1' 的步。</translation>
        </message>
        <message>
            <source>Only the first step of the chart is the initial step.</source>
            <translation>只有顺序功能图的第一个步是初始步。</translation>
        </message>
        <message>
            <source>This step has IEC actions. Remove them before making it a simplified step.</source>
            <translation>该步有 IEC 动作。请先移除它们,再将其设为简化步。</translation>
        </message>
        <message>
            <source>'%1' is not an action qualifier.</source>
            <translation>'%1' 不是动作限定符。</translation>
        </message>
        <message>
            <source>The qualifier %1 needs a time, such as T#5s.</source>
            <translation>限定符 %1 需要一个时间,例如 T#5s。</translation>
        </message>
        <message>
            <source>'%1' is not an action or variable name.</source>
            <translation>'%1' 不是动作名或变量名。</translation>
        </message>
        <message>
            <source>A simplified step has no IEC actions. Make it an IEC step in its properties first.</source>
            <translation>简化步没有 IEC 动作。请先在其属性中将其设为 IEC 步。</translation>
        </message>
        <message>
            <source>The step has no such action.</source>
            <translation>该步没有此动作。</translation>
        </message>
        <message>
            <source>The action cannot move there.</source>
            <translation>该动作不能移到那里。</translation>
        </message>
        <message>
            <source>Select a transition first.</source>
            <translation>请先选择一个转换。</translation>
        </message>
        <message>
            <source>A transition needs a condition, such as TRUE or Level &gt; 50.</source>
            <translation>转换需要一个条件,例如 TRUE 或 Level &gt; 50。</translation>
        </message>
        <message>
            <source>'%1' is not a valid transition name.</source>
            <translation>'%1' 不是有效的转换名称。</translation>
        </message>
        <message>
            <source>Select steps and transitions of one chain to copy.</source>
            <translation>请选择同一条链中的步和转换进行复制。</translation>
        </message>
        <message>
            <source>There is nothing to paste.</source>
            <translation>没有可粘贴的内容。</translation>
        </message>
        <message>
            <source>Select where to paste first.</source>
            <translation>请先选择粘贴位置。</translation>
        </message>
        <message>
            <source>The copied part does not fit here: after a step paste a part that starts with a transition, after a transition one that starts with a step.</source>
            <translation>复制的部分不适合放在这里:在步之后粘贴以转换开头的部分,在转换之后粘贴以步开头的部分。</translation>
        </message>
        <message>
            <source>The copied elements are not one chain of steps and transitions: nothing was pasted.</source>
            <translation>复制的元素不是一条由步和转换组成的链：未粘贴任何内容。</translation>
        </message>
        <message>
            <source>'%1' is not a valid action name: use letters, digits and single underscores, starting with a letter.</source>
            <translation>'%1' 不是有效的动作名称：请使用字母、数字和单个下划线，并以字母开头。</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::sfc::SfcItem</name>
        <message>
            <source>Initial step %1</source>
            <translation>初始步 %1</translation>
        </message>
        <message>
            <source>Step %1</source>
            <translation>步 %1</translation>
        </message>
        <message>
            <source>Entry action: %1</source>
            <translation>入口动作:%1</translation>
        </message>
        <message>
            <source>Exit action: %1</source>
            <translation>出口动作:%1</translation>
        </message>
        <message>
            <source>Active action: %1</source>
            <translation>活动动作:%1</translation>
        </message>
        <message>
            <source>Time: minimum %1, maximum %2</source>
            <translation>时间:最小 %1,最大 %2</translation>
        </message>
        <message>
            <source>Macro step %1 (double-click to open)</source>
            <translation>宏步 %1(双击打开)</translation>
        </message>
        <message>
            <source>Transition: %1</source>
            <translation>转换:%1</translation>
        </message>
        <message>
            <source>Jump to step %1</source>
            <translation>跳转到步 %1</translation>
        </message>
        <message>
            <source>Jump to step %1, which does not exist</source>
            <translation>跳转到不存在的步 %1</translation>
        </message>
        <message>
            <source>Parallel branch (start)</source>
            <translation>并行分支(开始)</translation>
        </message>
        <message>
            <source>Parallel branch (end)</source>
            <translation>并行分支(结束)</translation>
        </message>
        <message>
            <source>Alternative branch (start)</source>
            <translation>选择分支(开始)</translation>
        </message>
        <message>
            <source>Alternative branch (end)</source>
            <translation>选择分支(结束)</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::sfc::StepPropertiesDialog</name>
        <message>
            <source>Initial step</source>
            <translation>初始步</translation>
        </message>
        <message>
            <source>Simplified step (no IEC actions)</source>
            <translation>简化步(无 IEC 动作)</translation>
        </message>
        <message>
            <source>Step Properties</source>
            <translation>步属性</translation>
        </message>
        <message>
            <source>e.g. T#2s</source>
            <translation>例如 T#2s</translation>
        </message>
        <message>
            <source>e.g. T#10s</source>
            <translation>例如 T#10s</translation>
        </message>
        <message>
            <source>Name:</source>
            <translation>名称:</translation>
        </message>
        <message>
            <source>Entry action (E):</source>
            <translation>入口动作 (E):</translation>
        </message>
        <message>
            <source>Exit action (X):</source>
            <translation>出口动作 (X):</translation>
        </message>
        <message>
            <source>Active action:</source>
            <translation>活动动作:</translation>
        </message>
        <message>
            <source>Minimum time:</source>
            <translation>最小时间:</translation>
        </message>
        <message>
            <source>Maximum time:</source>
            <translation>最大时间:</translation>
        </message>
        <message>
            <source>Comment:</source>
            <translation>注释:</translation>
        </message>
    </context>
    <context>
        <name>iec::interp::Compiler</name>
        <message>
            <source>a statement</source>
            <translation>一条语句</translation>
        </message>
        <message>
            <source>VAR ... END_VAR</source>
            <translation>VAR ... END_VAR</translation>
        </message>
        <message>
            <source>the end of the text</source>
            <translation>文本结尾</translation>
        </message>
        <message>
            <source>'%1' is not valid IEC 61131-3 text.</source>
            <translation>'%1' 不是有效的 IEC 61131-3 文本。</translation>
        </message>
        <message>
            <source>Expected %1 but found %2.</source>
            <translation>应为 %1，但找到的是 %2。</translation>
        </message>
        <message>
            <source>close the string on the same line, and write $$ for a dollar sign</source>
            <translation>在同一行内结束字符串，美元符号写作 $$</translation>
        </message>
        <message>
            <source>check the digits and units of the literal, e.g. 16#FF or T#1s500ms</source>
            <translation>检查字面量的数字和单位，例如 16#FF 或 T#1s500ms</translation>
        </message>
        <message>
            <source>PROGRAM, FUNCTION_BLOCK, FUNCTION, TYPE or CONFIGURATION</source>
            <translation>PROGRAM、FUNCTION_BLOCK、FUNCTION、TYPE 或 CONFIGURATION</translation>
        </message>
        <message>
            <source>the name of the POU</source>
            <translation>POU 的名称</translation>
        </message>
        <message>
            <source>A FUNCTION needs a result type after its name.</source>
            <translation>FUNCTION 的名称后需要结果类型。</translation>
        </message>
        <message>
            <source>write e.g. FUNCTION %1 : INT</source>
            <translation>写成例如 FUNCTION %1 : INT</translation>
        </message>
        <message>
            <source>the name of the action</source>
            <translation>动作的名称</translation>
        </message>
        <message>
            <source>%1 has no %2.</source>
            <translation>%1 没有 %2。</translation>
        </message>
        <message>
            <source>add %1 after its last statement</source>
            <translation>在其最后一条语句后添加 %1</translation>
        </message>
        <message>
            <source>the name of a type</source>
            <translation>类型的名称</translation>
        </message>
        <message>
            <source>':' after the type name</source>
            <translation>类型名称后的 ':'</translation>
        </message>
        <message>
            <source>Missing ';' after the declaration of type %1.</source>
            <translation>类型 %1 的声明后缺少 ';'。</translation>
        </message>
        <message>
            <source>the name of the configuration</source>
            <translation>配置的名称</translation>
        </message>
        <message>
            <source>the name of the resource</source>
            <translation>资源的名称</translation>
        </message>
        <message>
            <source>the processor type after ON</source>
            <translation>ON 后面的处理器类型</translation>
        </message>
        <message>
            <source>the name of the task</source>
            <translation>任务的名称</translation>
        </message>
        <message>
            <source>'(' with the task's INTERVAL and PRIORITY</source>
            <translation>带有任务 INTERVAL 和 PRIORITY 的 '('</translation>
        </message>
        <message>
            <source>SINGLE, INTERVAL or PRIORITY</source>
            <translation>SINGLE、INTERVAL 或 PRIORITY</translation>
        </message>
        <message>
            <source>the name of the program instance</source>
            <translation>程序实例的名称</translation>
        </message>
        <message>
            <source>the task name after WITH</source>
            <translation>WITH 后面的任务名称</translation>
        </message>
        <message>
            <source>':' and the program type</source>
            <translation>':' 和程序类型</translation>
        </message>
        <message>
            <source>the program type</source>
            <translation>程序类型</translation>
        </message>
        <message>
            <source>TASK, PROGRAM or %1</source>
            <translation>TASK、PROGRAM 或 %1</translation>
        </message>
        <message>
            <source>This variable section has no END_VAR.</source>
            <translation>此变量段没有 END_VAR。</translation>
        </message>
        <message>
            <source>add END_VAR after its last declaration</source>
            <translation>在其最后一个声明后添加 END_VAR</translation>
        </message>
        <message>
            <source>a variable name</source>
            <translation>变量名</translation>
        </message>
        <message>
            <source>an address such as %IX0.0 after AT</source>
            <translation>AT 后面的地址，例如 %IX0.0</translation>
        </message>
        <message>
            <source>':' and a type</source>
            <translation>':' 和类型</translation>
        </message>
        <message>
            <source>An initial value is given with ':=', not '='.</source>
            <translation>初始值用 ':=' 给出，而不是 '='。</translation>
        </message>
        <message>
            <source>write %1 : ... := value;</source>
            <translation>写成 %1 : ... := 值;</translation>
        </message>
        <message>
            <source>Missing ';' after the declaration of %1.</source>
            <translation>%1 的声明后缺少 ';'。</translation>
        </message>
        <message>
            <source>'[' and the index range, e.g. ARRAY[1..10]</source>
            <translation>'[' 和下标范围，例如 ARRAY[1..10]</translation>
        </message>
        <message>
            <source>'..' between the bounds</source>
            <translation>上下限之间的 '..'</translation>
        </message>
        <message>
            <source>This STRUCT has no END_STRUCT.</source>
            <translation>此 STRUCT 没有 END_STRUCT。</translation>
        </message>
        <message>
            <source>an enumeration value</source>
            <translation>枚举值</translation>
        </message>
        <message>
            <source>')' after the enumeration values</source>
            <translation>枚举值后面的 ')'</translation>
        </message>
        <message>
            <source>the closing bracket of the string length</source>
            <translation>字符串长度的右括号</translation>
        </message>
        <message>
            <source>a type</source>
            <translation>类型</translation>
        </message>
        <message>
            <source>')' after the repeated value</source>
            <translation>重复值后面的 ')'</translation>
        </message>
        <message>
            <source>']' at the end of the array's initial values</source>
            <translation>数组初始值末尾的 ']'</translation>
        </message>
        <message>
            <source>a member name</source>
            <translation>成员名</translation>
        </message>
        <message>
            <source>')' at the end of the structure's initial values</source>
            <translation>结构初始值末尾的 ')'</translation>
        </message>
        <message>
            <source>INITIAL_STEP, STEP, TRANSITION or ACTION</source>
            <translation>INITIAL_STEP、STEP、TRANSITION 或 ACTION</translation>
        </message>
        <message>
            <source>the name of the step</source>
            <translation>步的名称</translation>
        </message>
        <message>
            <source>':' after the step name</source>
            <translation>步名称后的 ':'</translation>
        </message>
        <message>
            <source>an action name</source>
            <translation>动作名称</translation>
        </message>
        <message>
            <source>an action qualifier such as N, S, R, L or D</source>
            <translation>动作限定符，例如 N、S、R、L 或 D</translation>
        </message>
        <message>
            <source>a duration or an indicator variable</source>
            <translation>时间或指示变量</translation>
        </message>
        <message>
            <source>Missing ';' after the action association.</source>
            <translation>动作关联后缺少 ';'。</translation>
        </message>
        <message>
            <source>Step %1 has no END_STEP.</source>
            <translation>步 %1 没有 END_STEP。</translation>
        </message>
        <message>
            <source>a step name</source>
            <translation>步名称</translation>
        </message>
        <message>
            <source>')' after the step names</source>
            <translation>步名称后面的 ')'</translation>
        </message>
        <message>
            <source>':=' and the transition condition</source>
            <translation>':=' 和转换条件</translation>
        </message>
        <message>
            <source>This TRANSITION has no END_TRANSITION.</source>
            <translation>此 TRANSITION 没有 END_TRANSITION。</translation>
        </message>
        <message>
            <source>Missing ';' at the end of the statement.</source>
            <translation>语句末尾缺少 ';'。</translation>
        </message>
        <message>
            <source>every ST statement ends with ';'</source>
            <translation>每条 ST 语句都以 ';' 结尾</translation>
        </message>
        <message>
            <source>'=' compares two values; to assign a value write ':='.</source>
            <translation>'=' 用于比较两个值；赋值请写 ':='。</translation>
        </message>
        <message>
            <source>write %1 := ...;</source>
            <translation>写成 %1 := ...;</translation>
        </message>
        <message>
            <source>Expected ':=' or a call after '%1'.</source>
            <translation>'%1' 后面应为 ':=' 或调用。</translation>
        </message>
        <message>
            <source>This %1 has no matching %2.</source>
            <translation>此 %1 没有对应的 %2。</translation>
        </message>
        <message>
            <source>add %1; after the last statement that belongs to it</source>
            <translation>在属于它的最后一条语句后添加 %1;</translation>
        </message>
        <message>
            <source>A condition compares with '=', not ':='.</source>
            <translation>条件用 '=' 比较，而不是 ':='。</translation>
        </message>
        <message>
            <source>a case label such as 1:, 2, 3: or 10..20:</source>
            <translation>CASE 标号，例如 1:、2, 3: 或 10..20:</translation>
        </message>
        <message>
            <source>':' after the case label</source>
            <translation>CASE 标号后的 ':'</translation>
        </message>
        <message>
            <source>the control variable of the FOR loop</source>
            <translation>FOR 循环的控制变量</translation>
        </message>
        <message>
            <source>':=' and the start value</source>
            <translation>':=' 和起始值</translation>
        </message>
        <message>
            <source>This REPEAT has no UNTIL condition.</source>
            <translation>此 REPEAT 没有 UNTIL 条件。</translation>
        </message>
        <message>
            <source>a value</source>
            <translation>一个值</translation>
        </message>
        <message>
            <source>a value, a variable or a function call</source>
            <translation>值、变量或函数调用</translation>
        </message>
        <message>
            <source>a member name or a bit number after '.'</source>
            <translation>'.' 后面的成员名或位号</translation>
        </message>
        <message>
            <source>')' or ',' in the argument list</source>
            <translation>参数列表中的 ')' 或 ','</translation>
        </message>
        <message>
            <source>an IL operator such as LD, ST, ADD or JMP</source>
            <translation>指令表操作符，例如 LD、ST、ADD 或 JMP</translation>
        </message>
        <message>
            <source>An IL instruction takes one operand; %1 is left over.</source>
            <translation>指令表指令只有一个操作数；%1 是多余的。</translation>
        </message>
        <message>
            <source>put each instruction on its own line</source>
            <translation>每条指令单独写一行</translation>
        </message>
        <message>
            <source>There is no global variable %1 for this VAR_EXTERNAL.</source>
            <translation>没有与此 VAR_EXTERNAL 对应的全局变量 %1。</translation>
        </message>
        <message>
            <source>declare it in VAR_GLOBAL</source>
            <translation>在 VAR_GLOBAL 中声明</translation>
        </message>
        <message>
            <source>%1 is declared as %2 here but as %3 in VAR_GLOBAL.</source>
            <translation>%1 在此处声明为 %2，但在 VAR_GLOBAL 中声明为 %3。</translation>
        </message>
        <message>
            <source>%1 is a sequential function chart; charts run with the next version of the interpreter.</source>
            <translation>%1 是顺序功能图；顺序功能图将在下一版解释器中运行。</translation>
        </message>
        <message>
            <source>Only the first configuration (%1) runs.</source>
            <translation>只运行第一个配置（%1）。</translation>
        </message>
        <message>
            <source>SINGLE needs a global BOOL variable.</source>
            <translation>SINGLE 需要一个全局 BOOL 变量。</translation>
        </message>
        <message>
            <source>There is no PROGRAM called %1.</source>
            <translation>没有名为 %1 的 PROGRAM。</translation>
        </message>
        <message>
            <source>There is no task called %1.</source>
            <translation>没有名为 %1 的任务。</translation>
        </message>
        <message>
            <source>Recursion is not allowed in IEC 61131-3: %1 calls itself (%2).</source>
            <translation>IEC 61131-3 不允许递归：%1 调用了自身（%2）。</translation>
        </message>
        <message>
            <source>The type %1 is declared twice.</source>
            <translation>类型 %1 被声明了两次。</translation>
        </message>
        <message>
            <source>There are two POUs called %1.</source>
            <translation>有两个名为 %1 的 POU。</translation>
        </message>
        <message>
            <source>%1 is already the name of a type.</source>
            <translation>%1 已经是一个类型的名称。</translation>
        </message>
        <message>
            <source>The type %1 is defined in terms of itself.</source>
            <translation>类型 %1 是用自身定义的。</translation>
        </message>
        <message>
            <source>Unknown type '%1'.</source>
            <translation>未知类型 '%1'。</translation>
        </message>
        <message>
            <source>A string holds 1 to 65535 characters, not %1.</source>
            <translation>字符串可容纳 1 到 65535 个字符，而不是 %1。</translation>
        </message>
        <message>
            <source>The array range %1..%2 is empty; the upper bound must not be below the lower one.</source>
            <translation>数组范围 %1..%2 为空；上限不能小于下限。</translation>
        </message>
        <message>
            <source>This array needs %1 MB; an array may use at most 256 MB.</source>
            <translation>此数组需要 %1 MB；数组最多只能使用 256 MB。</translation>
        </message>
        <message>
            <source>A subrange needs an integer type, not %1.</source>
            <translation>子范围需要整数类型，而不是 %1。</translation>
        </message>
        <message>
            <source>The structure has two members called %1.</source>
            <translation>该结构有两个名为 %1 的成员。</translation>
        </message>
        <message>
            <source>%1 contains an instance of itself, which would never end.</source>
            <translation>%1 包含自身的实例，这将无穷无尽。</translation>
        </message>
        <message>
            <source>%1 is declared twice.</source>
            <translation>%1 被声明了两次。</translation>
        </message>
        <message>
            <source>A function cannot hold a function block instance (%1); use a function block instead.</source>
            <translation>函数不能包含功能块实例（%1）；请改用功能块。</translation>
        </message>
        <message>
            <source>The program needs more than 1 GB of memory for its variables.</source>
            <translation>该程序的变量需要超过 1 GB 的内存。</translation>
        </message>
        <message>
            <source>The global variable %1 is declared twice.</source>
            <translation>全局变量 %1 被声明了两次。</translation>
        </message>
        <message>
            <source>The address %1 does not fit a variable of type %2.</source>
            <translation>地址 %1 与类型为 %2 的变量不匹配。</translation>
        </message>
        <message>
            <source>A %1 is initialised with a single value.</source>
            <translation>%1 用单个值初始化。</translation>
        </message>
        <message>
            <source>There are more initial values than the array's %1 elements.</source>
            <translation>初始值多于数组的 %1 个元素。</translation>
        </message>
        <message>
            <source>An array is initialised with a list in brackets, e.g. [1, 2, 3] or [10(0)].</source>
            <translation>数组用方括号中的列表初始化，例如 [1, 2, 3] 或 [10(0)]。</translation>
        </message>
        <message>
            <source>%1 has no member %2.</source>
            <translation>%1 没有成员 %2。</translation>
        </message>
        <message>
            <source>A structure is initialised with (member := value, ...).</source>
            <translation>结构用 (成员 := 值, ...) 初始化。</translation>
        </message>
        <message>
            <source>The text has %1 characters but the string holds only %2.</source>
            <translation>文本有 %1 个字符，但字符串只能容纳 %2 个。</translation>
        </message>
        <message>
            <source>This must be a constant: a literal, a CONSTANT or an expression of them.</source>
            <translation>此处必须是常量：字面量、CONSTANT 或由它们组成的表达式。</translation>
        </message>
        <message>
            <source>This must be a constant integer.</source>
            <translation>此处必须是整数常量。</translation>
        </message>
        <message>
            <source>%1 is a constant and cannot be changed.</source>
            <translation>%1 是常量，不能修改。</translation>
        </message>
        <message>
            <source>%1 is an output of the function block and can only be read.</source>
            <translation>%1 是功能块的输出，只能读取。</translation>
        </message>
        <message>
            <source>%1 is internal to the function block.</source>
            <translation>%1 是功能块的内部变量。</translation>
        </message>
        <message>
            <source>%1 has no value %2.</source>
            <translation>%1 没有值 %2。</translation>
        </message>
        <message>
            <source>%1 is a value of several enumerations.</source>
            <translation>%1 是多个枚举的值。</translation>
        </message>
        <message>
            <source>write the type in front, e.g. Type#%1</source>
            <translation>在前面写上类型，例如 Type#%1</translation>
        </message>
        <message>
            <source>%1 is a POU, not a variable.</source>
            <translation>%1 是 POU，不是变量。</translation>
        </message>
        <message>
            <source>Unknown variable '%1'.</source>
            <translation>未知变量 '%1'。</translation>
        </message>
        <message>
            <source>declare it in a VAR section</source>
            <translation>在 VAR 段中声明</translation>
        </message>
        <message>
            <source>%1 is a %2 and has no members.</source>
            <translation>%1 是 %2，没有成员。</translation>
        </message>
        <message>
            <source>%1 has no bit %2.</source>
            <translation>%1 没有第 %2 位。</translation>
        </message>
        <message>
            <source>%1 is not an array.</source>
            <translation>%1 不是数组。</translation>
        </message>
        <message>
            <source>%1 has %2 dimension(s) but %3 index(es) are given.</source>
            <translation>%1 有 %2 维，但给出了 %3 个下标。</translation>
        </message>
        <message>
            <source>The index %1 is outside the range %2..%3 of %4.</source>
            <translation>下标 %1 超出 %4 的范围 %2..%3。</translation>
        </message>
        <message>
            <source>An array index must be an integer, not %1.</source>
            <translation>数组下标必须是整数，而不是 %1。</translation>
        </message>
        <message>
            <source>This is not a variable.</source>
            <translation>这不是变量。</translation>
        </message>
        <message>
            <source>The value %1 is outside the range %2..%3 of %4.</source>
            <translation>值 %1 超出 %4 的范围 %2..%3。</translation>
        </message>
        <message>
            <source>A function block instance cannot be assigned; call it instead.</source>
            <translation>不能给功能块实例赋值；请调用它。</translation>
        </message>
        <message>
            <source>'**' needs numbers, not %1 and %2.</source>
            <translation>'**' 需要数字，而不是 %1 和 %2。</translation>
        </message>
        <message>
            <source>'%1' cannot combine %2 and %3.</source>
            <translation>'%1' 不能组合 %2 和 %3。</translation>
        </message>
        <message>
            <source>BOOL or a bit string (BYTE, WORD, ...)</source>
            <translation>BOOL 或位串（BYTE、WORD 等）</translation>
        </message>
        <message>
            <source>integers</source>
            <translation>整数</translation>
        </message>
        <message>
            <source>numbers</source>
            <translation>数字</translation>
        </message>
        <message>
            <source>'%1' needs %2, not %3.</source>
            <translation>'%1' 需要 %2，而不是 %3。</translation>
        </message>
        <message>
            <source>Division by zero.</source>
            <translation>除以零。</translation>
        </message>
        <message>
            <source>A %1 cannot be negated.</source>
            <translation>%1 不能取负。</translation>
        </message>
        <message>
            <source>NOT needs BOOL or a bit string (BYTE, WORD, ...), not %1.</source>
            <translation>NOT 需要 BOOL 或位串（BYTE、WORD 等），而不是 %1。</translation>
        </message>
        <message>
            <source>an integer literal</source>
            <translation>整数字面量</translation>
        </message>
        <message>
            <source>'%1' is not a valid literal.</source>
            <translation>'%1' 不是有效的字面量。</translation>
        </message>
        <message>
            <source>A value of type %1 cannot be used as %2%3 without a conversion.</source>
            <translation>类型为 %1 的值不经转换不能用作 %2%3。</translation>
        </message>
        <message>
            <source>The value %1 does not fit into %2 (%3 to %4).</source>
            <translation>值 %1 超出 %2 的范围（%3 到 %4）。</translation>
        </message>
        <message>
            <source>The text has %1 characters but %2 holds only %3.</source>
            <translation>文本有 %1 个字符，但 %2 只能容纳 %3 个。</translation>
        </message>
        <message>
            <source>A %1 cannot be converted to text.</source>
            <translation>%1 不能转换为文本。</translation>
        </message>
        <message>
            <source>Text cannot be converted to %1.</source>
            <translation>文本不能转换为 %1。</translation>
        </message>
        <message>
            <source>A %1 cannot be converted to %2.</source>
            <translation>%1 不能转换为 %2。</translation>
        </message>
        <message>
            <source>convert it explicitly, e.g. %1_TO_%2(...)</source>
            <translation>请显式转换，例如 %1_TO_%2(...)</translation>
        </message>
        <message>
            <source>A function block call is a statement of its own.</source>
            <translation>功能块调用必须是单独的一条语句。</translation>
        </message>
        <message>
            <source>The action %1 takes no arguments.</source>
            <translation>动作 %1 不接受参数。</translation>
        </message>
        <message>
            <source>%1 is a %2, not a function block; it cannot be called.</source>
            <translation>%1 是 %2，不是功能块，不能调用。</translation>
        </message>
        <message>
            <source>call %1(...); then read its outputs, e.g. %1.Q</source>
            <translation>调用 %1(...)；然后读取其输出，例如 %1.Q</translation>
        </message>
        <message>
            <source>%1 is a function block type; declare an instance (e.g. inst : %1;) and call that.</source>
            <translation>%1 是功能块类型；请声明一个实例（例如 inst : %1;）并调用该实例。</translation>
        </message>
        <message>
            <source>%1 has no outputs to connect with '=&gt;'.</source>
            <translation>%1 没有可用 '=&gt;' 连接的输出。</translation>
        </message>
        <message>
            <source>Unknown function '%1'.</source>
            <translation>未知函数 '%1'。</translation>
        </message>
        <message>
            <source>%1 takes only %2 input(s).</source>
            <translation>%1 只有 %2 个输入。</translation>
        </message>
        <message>
            <source>%1 has no input or output called %2.</source>
            <translation>%1 没有名为 %2 的输入或输出。</translation>
        </message>
        <message>
            <source>%1 is not an output of %2; connect inputs with ':='.</source>
            <translation>%1 不是 %2 的输出；输入请用 ':=' 连接。</translation>
        </message>
        <message>
            <source>%1 is an output of %2; connect it with '=&gt;'.</source>
            <translation>%1 是 %2 的输出；请用 '=&gt;' 连接。</translation>
        </message>
        <message>
            <source>write %1 =&gt; variable</source>
            <translation>写成 %1 =&gt; 变量</translation>
        </message>
        <message>
            <source>%1 takes only %2 argument(s).</source>
            <translation>%1 只接受 %2 个参数。</translation>
        </message>
        <message>
            <source>%1 has no parameter called %2.</source>
            <translation>%1 没有名为 %2 的参数。</translation>
        </message>
        <message>
            <source>Connect inputs of %1 with ':=' and outputs with '=&gt;'.</source>
            <translation>%1 的输入用 ':=' 连接，输出用 '=&gt;' 连接。</translation>
        </message>
        <message>
            <source>%1 needs a variable for its VAR_IN_OUT %2.</source>
            <translation>%1 的 VAR_IN_OUT %2 需要一个变量。</translation>
        </message>
        <message>
            <source>%1 needs a REAL or LREAL, not %2.</source>
            <translation>%1 需要 REAL 或 LREAL，而不是 %2。</translation>
        </message>
        <message>
            <source>The inputs of %1 have types that do not go together (%2).</source>
            <translation>%1 的输入类型互不兼容（%2）。</translation>
        </message>
        <message>
            <source>%1 needs numbers, times or bit strings.</source>
            <translation>%1 需要数字、时间或位串。</translation>
        </message>
        <message>
            <source>%1 has no input %2.</source>
            <translation>%1 没有输入 %2。</translation>
        </message>
        <message>
            <source>%1 needs a bit string (BYTE, WORD, DWORD, LWORD), not %2.</source>
            <translation>%1 需要位串（BYTE、WORD、DWORD、LWORD），而不是 %2。</translation>
        </message>
        <message>
            <source>convert it first, e.g. %1_TO_%2</source>
            <translation>先进行转换，例如 %1_TO_%2</translation>
        </message>
        <message>
            <source>A length or position must be an integer, not %1.</source>
            <translation>长度或位置必须是整数，而不是 %1。</translation>
        </message>
        <message>
            <source>%1 needs a STRING or WSTRING, not %2.</source>
            <translation>%1 需要 STRING 或 WSTRING，而不是 %2。</translation>
        </message>
        <message>
            <source>This time function needs a %1, not %2.</source>
            <translation>此时间函数需要 %1，而不是 %2。</translation>
        </message>
        <message>
            <source>ABS needs a number, not %1.</source>
            <translation>ABS 需要数字，而不是 %1。</translation>
        </message>
        <message>
            <source>TRUNC needs a REAL or LREAL, not %1.</source>
            <translation>TRUNC 需要 REAL 或 LREAL，而不是 %1。</translation>
        </message>
        <message>
            <source>(the G input of SEL)</source>
            <translation>（SEL 的 G 输入）</translation>
        </message>
        <message>
            <source>The selector K of MUX must be an integer.</source>
            <translation>MUX 的选择器 K 必须是整数。</translation>
        </message>
        <message>
            <source>CONCAT_DATE_TOD needs a DATE and a TIME_OF_DAY.</source>
            <translation>CONCAT_DATE_TOD 需要一个 DATE 和一个 TIME_OF_DAY。</translation>
        </message>
        <message>
            <source>%1 takes one argument.</source>
            <translation>%1 只接受一个参数。</translation>
        </message>
        <message>
            <source>(the input of %1)</source>
            <translation>（%1 的输入）</translation>
        </message>
        <message>
            <source>%1 needs a bit string holding BCD digits.</source>
            <translation>%1 需要包含 BCD 数字的位串。</translation>
        </message>
        <message>
            <source>%1 takes %2%3 argument(s), not %4.</source>
            <translation>%1 接受 %2%3 个参数，而不是 %4 个。</translation>
        </message>
        <message>
            <source>at least </source>
            <translation>至少 </translation>
        </message>
        <message>
            <source>An argument of %1 is missing.</source>
            <translation>缺少 %1 的一个参数。</translation>
        </message>
        <message>
            <source>A condition must be BOOL, not %1.</source>
            <translation>条件必须是 BOOL，而不是 %1。</translation>
        </message>
        <message>
            <source>compare it, e.g. x &lt;&gt; 0</source>
            <translation>进行比较，例如 x &lt;&gt; 0</translation>
        </message>
        <message>
            <source>CASE needs an integer or an enumeration, not %1.</source>
            <translation>CASE 需要整数或枚举，而不是 %1。</translation>
        </message>
        <message>
            <source>The FOR loop needs an integer variable as its counter.</source>
            <translation>FOR 循环需要一个整数变量作为计数器。</translation>
        </message>
        <message>
            <source>(the end value)</source>
            <translation>（终值）</translation>
        </message>
        <message>
            <source>(the step)</source>
            <translation>（步长）</translation>
        </message>
        <message>
            <source>A FOR loop with step 0 never ends.</source>
            <translation>步长为 0 的 FOR 循环永远不会结束。</translation>
        </message>
        <message>
            <source>%1 is only allowed inside a FOR, WHILE or REPEAT loop.</source>
            <translation>%1 只能用在 FOR、WHILE 或 REPEAT 循环内。</translation>
        </message>
        <message>
            <source>%1 needs a current result; load one first with LD.</source>
            <translation>%1 需要当前结果；请先用 LD 装载一个值。</translation>
        </message>
        <message>
            <source>%1 needs an operand.</source>
            <translation>%1 需要一个操作数。</translation>
        </message>
        <message>
            <source>(the condition of %1)</source>
            <translation>（%1 的条件）</translation>
        </message>
        <message>
            <source>The label %1 is defined twice.</source>
            <translation>标号 %1 被定义了两次。</translation>
        </message>
        <message>
            <source>This ')' has no matching operator with '('.</source>
            <translation>此 ')' 没有对应的带 '(' 的操作符。</translation>
        </message>
        <message>
            <source>%1 needs a label to jump to.</source>
            <translation>%1 需要一个跳转标号。</translation>
        </message>
        <message>
            <source>%1 is not a function block with an input %2.</source>
            <translation>%1 不是具有输入 %2 的功能块。</translation>
        </message>
        <message>
            <source>This '(' is never closed with ')'.</source>
            <translation>此 '(' 从未用 ')' 闭合。</translation>
        </message>
        <message>
            <source>There is no label %1 to jump to.</source>
            <translation>没有可跳转的标号 %1。</translation>
        </message>
        <message>
            <source>This string is not closed on its line.</source>
            <translation>此字符串在本行内没有闭合。</translation>
        </message>
        <message>
            <source>Expected %1 but found '%2'.</source>
            <translation>应为 %1，但发现了 '%2'。</translation>
        </message>
        <message>
            <source>This ')' has no matching '('.</source>
            <translation>此 ')' 没有匹配的 '('。</translation>
        </message>
        <message>
            <source>did you mean %1?</source>
            <translation>您是否想写 %1？</translation>
        </message>
        <message>
            <source>the %1 of line %2 ends with %3</source>
            <translation>第 %2 行的 %1 以 %3 结束</translation>
        </message>
        <message>
            <source>ELSE IF opens a second IF that needs its own END_IF; write ELSIF instead</source>
            <translation>ELSE IF 会开启第二个 IF，它需要自己的 END_IF；请改写为 ELSIF</translation>
        </message>
        <message>
            <source>Expected a value, a variable or a function call but found '='.</source>
            <translation>应为值、变量或函数调用，但发现了 '='。</translation>
        </message>
        <message>
            <source>IEC 61131-3 compares with a single '='</source>
            <translation>IEC 61131-3 使用单个 '=' 进行比较</translation>
        </message>
        <message>
            <source>This is ST, but the body is written in IL; a body uses one language.</source>
            <translation>这是 ST，但该程序体是用 IL（指令表）编写的；一个程序体只能使用一种语言。</translation>
        </message>
        <message>
            <source>write it in IL (LD, ST, JMPC ...) or write the whole body in ST</source>
            <translation>用 IL（LD、ST、JMPC ……）编写，或将整个程序体改用 ST 编写</translation>
        </message>
        <message>
            <source>A %1 holds exactly one character, not %2.</source>
            <translation>%1 只能包含一个字符，而不是 %2 个。</translation>
        </message>
        <message>
            <source>VAR_IN_OUT %1 of %2 needs a variable, not a value.</source>
            <translation>%2 的 VAR_IN_OUT %1 需要一个变量，而不是一个值。</translation>
        </message>
        <message>
            <source>it may change what it is given; pass a variable</source>
            <translation>它可能修改传入的内容；请传入一个变量</translation>
        </message>
        <message>
            <source>%1 cannot be changed.</source>
            <translation>%1 不能被修改。</translation>
        </message>
        <message>
            <source>VAR_IN_OUT %1 of %2 may change the variable it is given</source>
            <translation>%2 的 VAR_IN_OUT %1 可能修改传入的变量</translation>
        </message>
        <message>
            <source>VAR_IN_OUT %1 of %2 needs a variable of type %3, not %4.</source>
            <translation>%2 的 VAR_IN_OUT %1 需要 %3 类型的变量，而不是 %4。</translation>
        </message>
        <message>
            <source>VAR_IN_OUT passes the variable itself, so no conversion is possible; use a variable of type %1</source>
            <translation>VAR_IN_OUT 传递的是变量本身，因此无法进行类型转换；请使用 %1 类型的变量</translation>
        </message>
        <message>
            <source>A call gives either all its arguments by name or none; here only some have a name.</source>
            <translation>调用要么所有实参都带名称，要么都不带；此处只有部分带名称。</translation>
        </message>
        <message>
            <source>write each argument as name := value</source>
            <translation>将每个实参写成 名称 := 值</translation>
        </message>
        <message>
            <source>pass it in every call, e.g. %1(%2 := variable)</source>
            <translation>每次调用都要传入，例如 %1(%2 := 变量)</translation>
        </message>
        <message>
            <source>This FOR loop ends by setting %1 to %2, outside its range %3..%4, which stops the program.</source>
            <translation>此 FOR 循环结束时会将 %1 设为 %2，超出其范围 %3..%4，这会使程序停止。</translation>
        </message>
        <message>
            <source>This FOR loop ends by setting %1 beyond %2, outside its range %3..%4, which stops the program.</source>
            <translation>此 FOR 循环结束时会将 %1 设为超过 %2 的值，超出其范围 %3..%4，这会使程序停止。</translation>
        </message>
        <message>
            <source>give %1 a type with room for the value that ends the loop</source>
            <translation>为 %1 选择一个能容纳循环结束值的类型</translation>
        </message>
        <message>
            <source>This FOR loop never ends: %1 wraps around before it can pass %2.</source>
            <translation>此 FOR 循环永不结束：%1 在超过 %2 之前就会溢出回绕。</translation>
        </message>
        <message>
            <source>use a larger type than %1 for %2</source>
            <translation>为 %2 使用比 %1 更大的类型</translation>
        </message>
        <message>
            <source>The case value %1 is already handled on line %2; only the first branch runs for it.</source>
            <translation>CASE 值 %1 已在第 %2 行处理；对该值只执行第一个分支。</translation>
        </message>
        <message>
            <source>The value %1 does not fit into %2.</source>
            <translation>值 %1 超出了 %2 的范围。</translation>
        </message>
        <message>
            <source>The global list %1 has no variable %2.</source>
            <translation>全局变量列表 %1 中没有变量 %2。</translation>
        </message>
        <message>
            <source>The pragma {%1} means nothing to IEC Studio; it is ignored.</source>
            <translation>编译指令 {%1} 对 IEC Studio 没有意义，已忽略。</translation>
        </message>
        <message>
            <source>the name it extends</source>
            <translation>所扩展的名称</translation>
        </message>
        <message>
            <source>the name of an interface</source>
            <translation>接口的名称</translation>
        </message>
        <message>
            <source>the name of the method</source>
            <translation>方法的名称</translation>
        </message>
        <message>
            <source>The method %1 has no END_METHOD.</source>
            <translation>方法 %1 缺少 END_METHOD。</translation>
        </message>
        <message>
            <source>the name of the property</source>
            <translation>属性的名称</translation>
        </message>
        <message>
            <source>':' and the type of the property</source>
            <translation>':' 和属性的类型</translation>
        </message>
        <message>
            <source>The property %1 has no END_PROPERTY.</source>
            <translation>属性 %1 缺少 END_PROPERTY。</translation>
        </message>
        <message>
            <source>This expression is nested too deeply (more than %1 levels).</source>
            <translation>该表达式嵌套过深（超过 %1 层）。</translation>
        </message>
        <message>
            <source>split it into several statements, with variables for the parts</source>
            <translation>把它拆成几条语句，用变量保存各部分</translation>
        </message>
        <message>
            <source>These statements are nested too deeply (more than %1 levels).</source>
            <translation>这些语句嵌套过深（超过 %1 层）。</translation>
        </message>
        <message>
            <source>move the inner blocks into a function, a function block or an action</source>
            <translation>把内层语句块移到函数、功能块或动作中</translation>
        </message>
        <message>
            <source>This type is nested too deeply (more than %1 levels).</source>
            <translation>该类型嵌套过深（超过 %1 层）。</translation>
        </message>
        <message>
            <source>declare the inner types as types of their own in a TYPE block</source>
            <translation>在 TYPE 块中把内层类型声明为独立的类型</translation>
        </message>
        <message>
            <source>This initial value is nested too deeply (more than %1 levels).</source>
            <translation>该初始值嵌套过深（超过 %1 层）。</translation>
        </message>
        <message>
            <source>This is nested too deeply to compile.</source>
            <translation>嵌套过深，无法编译。</translation>
        </message>
        <message>
            <source>split it into simpler steps: constants, types and function blocks defined in fewer steps, expressions with fewer levels</source>
            <translation>把它拆成更简单的部分：常量、类型和功能块用更少的层次定义，表达式用更少的嵌套</translation>
        </message>
        <message>
            <source>%1 is FINAL; no function block can extend it.</source>
            <translation>%1 是 FINAL，任何功能块都不能扩展它。</translation>
        </message>
        <message>
            <source>%1 extends %2, which is no function block.</source>
            <translation>%1 扩展了 %2，但 %2 不是功能块。</translation>
        </message>
        <message>
            <source>%1 is ABSTRACT; declare an instance of a function block that extends it.</source>
            <translation>%1 是 ABSTRACT；请声明一个扩展它的功能块的实例。</translation>
        </message>
        <message>
            <source>A %1 starts at 0; set it in the code instead (p := ADR(x); or r REF= x;).</source>
            <translation>%1 的初始值为 0；请在代码中为它赋值（p := ADR(x); 或 r REF= x;）。</translation>
        </message>
        <message>
            <source>This constant is defined in terms of itself.</source>
            <translation>该常量是用它自身定义的。</translation>
        </message>
        <message>
            <source>%1 combines BOOL values, not %2.</source>
            <translation>%1 只能组合 BOOL 值，不能组合 %2。</translation>
        </message>
        <message>
            <source>Implicit conversion from %1 to %2: possible loss of information.</source>
            <translation>从 %1 到 %2 的隐式转换：可能丢失信息。</translation>
        </message>
        <message>
            <source>Implicit conversion from signed type %1 to unsigned type %2: possible change of sign.</source>
            <translation>从有符号类型 %1 到无符号类型 %2 的隐式转换：符号可能改变。</translation>
        </message>
        <message>
            <source>Implicit conversion from unsigned type %1 to signed type %2: possible change of sign.</source>
            <translation>从无符号类型 %1 到有符号类型 %2 的隐式转换：符号可能改变。</translation>
        </message>
        <message>
            <source>SUPER^() calls the body of the block this one extends; it is only known in such a block's body.</source>
            <translation>SUPER^() 调用本功能块所扩展的功能块的主体，只能在这样的功能块主体中使用。</translation>
        </message>
        <message>
            <source>A program call is a statement of its own.</source>
            <translation>程序调用必须是单独的一条语句。</translation>
        </message>
        <message>
            <source>call %1(...); then read its outputs, e.g. %1.Out</source>
            <translation>先调用 %1(...);，再读取它的输出，例如 %1.Out</translation>
        </message>
        <message>
            <source>The program %1 runs in %2 instances; its name alone does not say which.</source>
            <translation>程序 %1 有 %2 个实例在运行，仅凭名称无法确定是哪一个。</translation>
        </message>
        <message>
            <source>give each instance its own program, or reach the values through a global variable</source>
            <translation>为每个实例使用单独的程序，或通过全局变量访问这些值</translation>
        </message>
        <message>
            <source>(the current result at label %1)</source>
            <translation>（标号 %1 处的当前结果）</translation>
        </message>
        <message>
            <source>%1 is a %2, not a pointer; only a pointer is dereferenced with ^.</source>
            <translation>%1 是 %2，不是指针；只有指针才能用 ^ 取值。</translation>
        </message>
        <message>
            <source>%1 needs a variable (not a constant or a single bit).</source>
            <translation>%1 需要一个变量（不能是常量或单个位）。</translation>
        </message>
        <message>
            <source>__ISVALIDREF needs a REFERENCE TO variable, not %1.</source>
            <translation>__ISVALIDREF 需要 REFERENCE TO 变量，而不是 %1。</translation>
        </message>
        <message>
            <source>REF= needs a REFERENCE TO variable on its left, not %1.</source>
            <translation>REF= 左边需要 REFERENCE TO 变量，而不是 %1。</translation>
        </message>
        <message>
            <source>to assign a value write :=</source>
            <translation>赋值请写 :=</translation>
        </message>
        <message>
            <source>%1 can refer to a variable of type %2, not to %3.</source>
            <translation>%1 只能引用 %2 类型的变量，不能引用 %3。</translation>
        </message>
        <message>
            <source>a constant</source>
            <translation>常量</translation>
        </message>
        <message>
            <source>A pointer can only be moved with + and -, and compared.</source>
            <translation>指针只能用 + 和 - 移动，以及进行比较。</translation>
        </message>
        <message>
            <source>Two pointers cannot be added; add a number of bytes to one.</source>
            <translation>两个指针不能相加；请给其中一个加上字节数。</translation>
        </message>
        <message>
            <source>the OpenPLC TCP socket library</source>
            <translation>OpenPLC 的 TCP 套接字库</translation>
        </message>
        <message>
            <source>an MQTT library</source>
            <translation>MQTT 库</translation>
        </message>
        <message>
            <source>CODESYS SoftMotion (PLCopen motion control)</source>
            <translation>CODESYS SoftMotion（PLCopen 运动控制）</translation>
        </message>
        <message>
            <source>CODESYS SoftMotion</source>
            <translation>CODESYS SoftMotion 运动控制库</translation>
        </message>
        <message>
            <source>the OpenPLC UDP socket library</source>
            <translation>OpenPLC 的 UDP 套接字库</translation>
        </message>
        <message>
            <source>Beremiz's Python blocks</source>
            <translation>Beremiz 的 Python 功能块</translation>
        </message>
        <message>
            <source>%1 is a block of %2, which IEC Studio does not have; the POUs that use it cannot run.</source>
            <translation>%1 是 %2 中的功能块，IEC Studio 没有该库；使用它的 POU 无法运行。</translation>
        </message>
        <message>
            <source>the rest of the project is still checked and runs</source>
            <translation>项目的其余部分仍会检查并运行</translation>
        </message>
        <message>
            <source>%1 cannot run: %2 uses %3.</source>
            <translation>%1 无法运行：%2 使用了 %3。</translation>
        </message>
        <message>
            <source>%1 has two methods or properties called %2.</source>
            <translation>%1 有两个名为 %2 的方法或属性。</translation>
        </message>
        <message>
            <source>%1 is %2 and cannot be called from here.</source>
            <translation>%1 是 %2，不能从此处调用。</translation>
        </message>
        <message>
            <source>SUPER is only known in a function block that EXTENDS another one.</source>
            <translation>SUPER 只能在扩展（EXTENDS）了另一个功能块的功能块中使用。</translation>
        </message>
        <message>
            <source>THIS is only known in a function block and its methods.</source>
            <translation>THIS 只能在功能块及其方法中使用。</translation>
        </message>
        <message>
            <source>No function block implements %1.%2, so it cannot be called.</source>
            <translation>没有功能块实现 %1.%2，因此不能调用它。</translation>
        </message>
        <message>
            <source>%1 is ABSTRACT and has no code to run.</source>
            <translation>%1 是 ABSTRACT，没有可运行的代码。</translation>
        </message>
        <message>
            <source>The property %1 has no SET and cannot be written.</source>
            <translation>属性 %1 没有 SET，不能写入。</translation>
        </message>
        <message>
            <source>The property %1 has no GET and cannot be read.</source>
            <translation>属性 %1 没有 GET，不能读取。</translation>
        </message>
        <message>
            <source>%1 does not extend %2.</source>
            <translation>%1 没有扩展 %2。</translation>
        </message>
        <message>
            <source>%1 does not implement %2.</source>
            <translation>%1 没有实现 %2。</translation>
        </message>
        <message>
            <source>%1 is an SFC chart that contains itself.</source>
            <translation>%1 是包含自身的顺序功能图。</translation>
        </message>
        <message>
            <source>This IL condition is nested too deeply (more than %1 levels).</source>
            <translation>该 IL 条件嵌套过深（超过 %1 层）。</translation>
        </message>
        <message>
            <source>The action %1 of step %2 is a variable of type %3; it is 1 while the action is active and 0 otherwise.</source>
            <translation>步 %2 的动作 %1 是 %3 类型的变量；动作激活时为 1，否则为 0。</translation>
        </message>
        <message>
            <source>%1 is a program, not a type; only function blocks can be instantiated.</source>
            <translation>%1 是程序，不是类型；只有功能块可以实例化。</translation>
        </message>
        <message>
            <source>%1 is a function, not a type; only function blocks can be instantiated.</source>
            <translation>%1 是函数，不是类型；只有功能块可以实例化。</translation>
        </message>
        <message>
            <source>%1 is written in %2, which has no IEC text form; its body was left out.</source>
            <translation>%1 是用 %2 编写的，%2 没有 IEC 文本形式；其主体已省略。</translation>
        </message>
        <message>
            <source>The entry, exit and active actions and the times of steps %1 have no IEC text form and were left out.</source>
            <translation>步 %1 的进入动作、退出动作、激活动作和时间没有 IEC 文本形式，已省略。</translation>
        </message>
        <message>
            <source>VAR_CONFIG cannot be stored in a PLCopen project yet and was left out.</source>
            <translation>VAR_CONFIG 暂时无法保存到 PLCopen 项目中，已省略。</translation>
        </message>
        <message>
            <source>The priority of task %1 must be a number from 0 to 65535; 0 is used.</source>
            <translation>任务 %1 的优先级必须是 0 到 65535 之间的数；将使用 0。</translation>
        </message>
        <message>
            <source>The arguments of program instance %1 cannot be stored in a PLCopen project and were left out.</source>
            <translation>程序实例 %1 的参数无法保存到 PLCopen 项目中，已省略。</translation>
        </message>
        <message>
            <source>VAR_GLOBAL outside a CONFIGURATION cannot be stored in a PLCopen project; put it inside the CONFIGURATION.</source>
            <translation>CONFIGURATION 之外的 VAR_GLOBAL 无法保存到 PLCopen 项目中；请把它放进 CONFIGURATION。</translation>
        </message>
        <message>
            <source>The vendor element '%1' cannot run in this version.</source>
            <translation>厂商专用元素 '%1' 在此版本中无法运行。</translation>
        </message>
        <message>
            <source>This element could not be read from the file, so it cannot run.</source>
            <translation>无法从文件中读取该元素，因此它不能运行。</translation>
        </message>
        <message>
            <source>A %1 belongs in an SFC chart, not in an LD or FBD network.</source>
            <translation>%1 属于顺序功能图，不能用在梯形图或功能块图网络中。</translation>
        </message>
        <message>
            <source>Two labels are called '%1'.</source>
            <translation>有两个标号都叫 '%1'。</translation>
        </message>
        <message>
            <source>rename one of them</source>
            <translation>请重命名其中一个</translation>
        </message>
        <message>
            <source>This condition</source>
            <translation>该条件</translation>
        </message>
        <message>
            <source>comment</source>
            <translation>注释</translation>
        </message>
        <message>
            <source>unreadable element</source>
            <translation>无法读取的元素</translation>
        </message>
        <message>
            <source>connector</source>
            <translation>连接符</translation>
        </message>
        <message>
            <source>continuation</source>
            <translation>续接符</translation>
        </message>
        <message>
            <source>action block</source>
            <translation>动作块</translation>
        </message>
        <message>
            <source>vendor element</source>
            <translation>厂商专用元素</translation>
        </message>
        <message>
            <source>block</source>
            <translation>功能块框</translation>
        </message>
        <message>
            <source>input variable</source>
            <translation>输入变量</translation>
        </message>
        <message>
            <source>output variable</source>
            <translation>输出变量</translation>
        </message>
        <message>
            <source>in-out variable</source>
            <translation>输入输出变量</translation>
        </message>
        <message>
            <source>label</source>
            <translation>标号</translation>
        </message>
        <message>
            <source>jump</source>
            <translation>跳转</translation>
        </message>
        <message>
            <source>return</source>
            <translation>返回</translation>
        </message>
        <message>
            <source>left power rail</source>
            <translation>左母线</translation>
        </message>
        <message>
            <source>right power rail</source>
            <translation>右母线</translation>
        </message>
        <message>
            <source>coil</source>
            <translation>线圈</translation>
        </message>
        <message>
            <source>contact</source>
            <translation>触点</translation>
        </message>
        <message>
            <source>step</source>
            <translation>步</translation>
        </message>
        <message>
            <source>macro step</source>
            <translation>宏步</translation>
        </message>
        <message>
            <source>transition</source>
            <translation>转换</translation>
        </message>
        <message>
            <source>selection divergence</source>
            <translation>选择分支</translation>
        </message>
        <message>
            <source>selection convergence</source>
            <translation>选择合并</translation>
        </message>
        <message>
            <source>simultaneous divergence</source>
            <translation>并行分支</translation>
        </message>
        <message>
            <source>simultaneous convergence</source>
            <translation>并行合并</translation>
        </message>
        <message>
            <source>An element has no variable or value written in it.</source>
            <translation>有一个元素中没有填写变量或数值。</translation>
        </message>
        <message>
            <source>enter a variable name or a constant</source>
            <translation>请输入变量名或常量</translation>
        </message>
        <message>
            <source>'%1' is not a variable or an expression.</source>
            <translation>'%1' 不是变量，也不是表达式。</translation>
        </message>
        <message>
            <source>write a name such as Motor, Tank.Level or %QX0.1, or a constant such as T#5s</source>
            <translation>请写一个名称（如 Motor、Tank.Level 或 %QX0.1）或一个常量（如 T#5s）</translation>
        </message>
        <message>
            <source>Two elements have the same localId %1.</source>
            <translation>有两个元素的 localId 都是 %1。</translation>
        </message>
        <message>
            <source>give every element its own localId</source>
            <translation>请给每个元素分配唯一的 localId</translation>
        </message>
        <message>
            <source>There is no connector named '%1' for this continuation.</source>
            <translation>没有与该续接符对应的名为 '%1' 的连接符。</translation>
        </message>
        <message>
            <source>add a connector with that name where the wire starts</source>
            <translation>请在连线的起点添加同名的连接符</translation>
        </message>
        <message>
            <source>The wires make a loop through %1 elements with no variable to keep the value from one scan to the next.</source>
            <translation>连线经过 %1 个元素形成了回路，其中没有变量在两个扫描周期之间保存数值。</translation>
        </message>
        <message>
            <source>put a feedback variable (an in-out variable) into the loop</source>
            <translation>请在回路中加入一个反馈变量（输入输出变量）</translation>
        </message>
        <message>
            <source>%1 cannot be used in a condition wired into a chart.</source>
            <translation>%1 不能用在连接到顺序功能图的条件中。</translation>
        </message>
        <message>
            <source>write the condition as a named transition instead</source>
            <translation>请改为把条件写成命名的转换</translation>
        </message>
        <message>
            <source>A wire comes from element %1, which is not in this diagram.</source>
            <translation>有一条连线来自元素 %1，但该元素不在此图中。</translation>
        </message>
        <message>
            <source>A wire comes from an element that gives no value (%1).</source>
            <translation>有一条连线来自不提供数值的元素（%1）。</translation>
        </message>
        <message>
            <source>A wire comes from the output '%1', which %2 does not have.</source>
            <translation>有一条连线来自输出 '%1'，但 %2 没有该输出。</translation>
        </message>
        <message>
            <source>A wire comes from a %1, which gives no value.</source>
            <translation>有一条连线来自%1，而%1不提供数值。</translation>
        </message>
        <message>
            <source>draw a wire to it</source>
            <translation>请给它连一条线</translation>
        </message>
        <message>
            <source>%1 wires end at one input; an input takes exactly one.</source>
            <translation>有 %1 条连线接到同一个输入上；一个输入只能接一条连线。</translation>
        </message>
        <message>
            <source>combine them with an OR block</source>
            <translation>请用 OR 功能块把它们组合起来</translation>
        </message>
        <message>
            <source>%1 is not connected.</source>
            <translation>%1 未连接。</translation>
        </message>
        <message>
            <source>An edge detection</source>
            <translation>边沿检测</translation>
        </message>
        <message>
            <source>Nothing is wired to the connector '%1'.</source>
            <translation>连接符 '%1' 上没有连线。</translation>
        </message>
        <message>
            <source>The contact '%1' has no wire on its left.</source>
            <translation>触点 '%1' 的左侧没有连线。</translation>
        </message>
        <message>
            <source>The coil '%1' has no wire on its left.</source>
            <translation>线圈 '%1' 的左侧没有连线。</translation>
        </message>
        <message>
            <source>A coil</source>
            <translation>线圈</translation>
        </message>
        <message>
            <source>Nothing is wired to the output '%1'.</source>
            <translation>输出 '%1' 上没有连线。</translation>
        </message>
        <message>
            <source>An output variable</source>
            <translation>输出变量</translation>
        </message>
        <message>
            <source>A variable that is written</source>
            <translation>被写入的变量</translation>
        </message>
        <message>
            <source>The input %1 of %2 is not connected.</source>
            <translation>%2 的输入 %1 未连接。</translation>
        </message>
        <message>
            <source>draw a wire to it or write a constant</source>
            <translation>请给它连线或写一个常量</translation>
        </message>
        <message>
            <source>A function block</source>
            <translation>功能块</translation>
        </message>
        <message>
            <source>Only the result of the function %1 can be wired; its output %2 cannot yet.</source>
            <translation>函数 %1 只有返回值可以连线，其输出 %2 暂时还不能连线。</translation>
        </message>
        <message>
            <source>call %1 from ST to use its other outputs</source>
            <translation>请在 ST 中调用 %1 以使用它的其他输出</translation>
        </message>
        <message>
            <source>A function call</source>
            <translation>函数调用</translation>
        </message>
        <message>
            <source>A function with EN</source>
            <translation>带 EN 的函数</translation>
        </message>
        <message>
            <source>The result type of %1 cannot be told here, so it cannot run under EN.</source>
            <translation>此处无法确定 %1 的返回类型，因此它不能在 EN 控制下运行。</translation>
        </message>
        <message>
            <source>wire its output to a variable, or leave EN open</source>
            <translation>请把它的输出连到一个变量上，或让 EN 保持未连接</translation>
        </message>
        <message>
            <source>This EXECUTE box holds no ST code.</source>
            <translation>该 EXECUTE 框中没有 ST 代码。</translation>
        </message>
        <message>
            <source>The ST code of this EXECUTE box does not parse: %1</source>
            <translation>该 EXECUTE 框中的 ST 代码无法解析：%1</translation>
        </message>
        <message>
            <source>An EXECUTE box</source>
            <translation>EXECUTE 框</translation>
        </message>
        <message>
            <source>The jump to '%1' has no condition wired to it.</source>
            <translation>跳转到 '%1' 的跳转没有连接条件。</translation>
        </message>
        <message>
            <source>There is no label '%1' to jump to.</source>
            <translation>没有可跳转的标号 '%1'。</translation>
        </message>
        <message>
            <source>add a label with that name, or correct the jump</source>
            <translation>请添加同名的标号，或修改跳转</translation>
        </message>
        <message>
            <source>A jump</source>
            <translation>跳转</translation>
        </message>
        <message>
            <source>The return has no condition wired to it.</source>
            <translation>返回没有连接条件。</translation>
        </message>
        <message>
            <source>A return</source>
            <translation>返回</translation>
        </message>
        <message>
            <source>A step has no name.</source>
            <translation>有一个步没有名称。</translation>
        </message>
        <message>
            <source>give every step a unique name</source>
            <translation>请给每个步起一个唯一的名称</translation>
        </message>
        <message>
            <source>Two steps are called %1; every step of a chart needs its own name.</source>
            <translation>有两个步都叫 %1；顺序功能图中每个步都需要唯一的名称。</translation>
        </message>
        <message>
            <source>Macro step %1 has no steps inside.</source>
            <translation>宏步 %1 内部没有步。</translation>
        </message>
        <message>
            <source>The transition is connected to element %1, which the chart does not have.</source>
            <translation>该转换连接到元素 %1，但顺序功能图中没有该元素。</translation>
        </message>
        <message>
            <source>A transition must come after a step, a selection divergence or a simultaneous convergence, not after a %1.</source>
            <translation>转换必须位于步、选择分支或并行合并之后，而不能位于%1之后。</translation>
        </message>
        <message>
            <source>Two transitions follow each other; put a step between them.</source>
            <translation>两个转换直接相连；请在它们之间加入一个步。</translation>
        </message>
        <message>
            <source>A transition must lead to a step, a jump, a simultaneous divergence or a selection convergence, not to a %1.</source>
            <translation>转换之后必须是步、跳转、并行分支或选择合并，而不能是%1。</translation>
        </message>
        <message>
            <source>This transition has no step before it.</source>
            <translation>该转换之前没有步。</translation>
        </message>
        <message>
            <source>connect it below a step</source>
            <translation>请把它连接到某个步的下方</translation>
        </message>
        <message>
            <source>This transition leads to no step.</source>
            <translation>该转换之后没有步。</translation>
        </message>
        <message>
            <source>connect a step or a jump below it</source>
            <translation>请在它下方连接一个步或跳转</translation>
        </message>
        <message>
            <source>This transition has no condition.</source>
            <translation>该转换没有转换条件。</translation>
        </message>
        <message>
            <source>write a condition such as TRUE or Start AND NOT Stop</source>
            <translation>请写一个条件，例如 TRUE 或 Start AND NOT Stop</translation>
        </message>
        <message>
            <source>Step %1 has no transition after it.</source>
            <translation>步 %1 之后没有转换。</translation>
        </message>
        <message>
            <source>add a transition below it, or a jump back</source>
            <translation>请在它下方添加一个转换，或跳转回前面的步</translation>
        </message>
        <message>
            <source>The jump goes to step %1, which the chart does not have.</source>
            <translation>跳转的目标是步 %1，但顺序功能图中没有该步。</translation>
        </message>
        <message>
            <source>Each branch of a selection divergence must begin with a transition, not a %1.</source>
            <translation>选择分支的每个分支都必须以转换开始，而不能以%1开始。</translation>
        </message>
        <message>
            <source>A selection divergence must come after a step, not after a %1.</source>
            <translation>选择分支必须位于步之后，而不能位于%1之后。</translation>
        </message>
        <message>
            <source>Each branch of a simultaneous divergence must begin with a step, not a %1.</source>
            <translation>并行分支的每个分支都必须以步开始，而不能以%1开始。</translation>
        </message>
        <message>
            <source>A simultaneous divergence must come after a transition, not after a %1.</source>
            <translation>并行分支必须位于转换之后，而不能位于%1之后。</translation>
        </message>
        <message>
            <source>Each branch of a selection convergence must end with a transition, not a %1.</source>
            <translation>选择合并的每个分支都必须以转换结束，而不能以%1结束。</translation>
        </message>
        <message>
            <source>A selection convergence must lead to a step, not to a %1.</source>
            <translation>选择合并之后必须是步，而不能是%1。</translation>
        </message>
        <message>
            <source>Each branch of a simultaneous convergence must end with a step, not a %1.</source>
            <translation>并行合并的每个分支都必须以步结束，而不能以%1结束。</translation>
        </message>
        <message>
            <source>A simultaneous convergence must lead to a transition, not to a %1.</source>
            <translation>并行合并之后必须是转换，而不能是%1。</translation>
        </message>
        <message>
            <source>This action block is not connected to a step.</source>
            <translation>该动作块没有连接到步。</translation>
        </message>
        <message>
            <source>An action block must be connected to a step.</source>
            <translation>动作块必须连接到步。</translation>
        </message>
        <message>
            <source>This action of step %1 names no action.</source>
            <translation>步 %1 的这个动作没有指定动作名称。</translation>
        </message>
        <message>
            <source>%1 is not an action qualifier; use N, R, S, L, D, P, P0, P1, SD, DS or SL.</source>
            <translation>%1 不是动作限定符；请使用 N、R、S、L、D、P、P0、P1、SD、DS 或 SL。</translation>
        </message>
        <message>
            <source>The qualifier %1 of action %2 needs a duration, e.g. T#5s.</source>
            <translation>动作 %2 的限定符 %1 需要一个时间，例如 T#5s。</translation>
        </message>
        <message>
            <source>The chart of %1 has no initial step.</source>
            <translation>%1 的顺序功能图没有初始步。</translation>
        </message>
        <message>
            <source>make one step the initial step (double frame)</source>
            <translation>请把一个步设为初始步（双线框）</translation>
        </message>
        <message>
            <source>Step %1 is a second initial step; a chart has exactly one (the first is %2).</source>
            <translation>步 %1 是第二个初始步；一个顺序功能图只能有一个初始步（第一个是 %2）。</translation>
        </message>
        <message>
            <source>The chart's code for this element does not parse: %1</source>
            <translation>顺序功能图中该元素的代码无法解析：%1</translation>
        </message>
        <message>
            <source>%1 is the name of a variable and of the chart's implicit variable; rename one of them.</source>
            <translation>%1 既是一个变量的名称，又是顺序功能图隐式变量的名称；请重命名其中一个。</translation>
        </message>
        <message>
            <source>The chart's variables cannot be declared: %1</source>
            <translation>无法声明顺序功能图的变量：%1</translation>
        </message>
        <message>
            <source>This inline action is written in IL; an inline action must be written in ST, LD or FBD.</source>
            <translation>该内嵌动作是用 IL 编写的；内嵌动作必须用 ST、LD 或 FBD 编写。</translation>
        </message>
        <message>
            <source>make it an action of %1 and name it in the step</source>
            <translation>请把它改为 %1 的动作，并在步中引用它的名称</translation>
        </message>
        <message>
            <source>Step %1 runs action %2, which %3 does not have.</source>
            <translation>步 %1 执行动作 %2，但 %3 中没有该动作。</translation>
        </message>
        <message>
            <source>This IL condition uses jumps, parentheses or calls, which a transition cannot run yet.</source>
            <translation>该 IL 条件使用了跳转、括号或调用，转换暂时还不能执行这些。</translation>
        </message>
        <message>
            <source>write the condition as an ST expression</source>
            <translation>请把条件写成 ST 表达式</translation>
        </message>
        <message>
            <source>A graphical transition condition needs a name: its network assigns that name.</source>
            <translation>图形化的转换条件需要一个名称：由它的网络给该名称赋值。</translation>
        </message>
        <message>
            <source>A transition condition cannot be an SFC chart.</source>
            <translation>转换条件不能是顺序功能图。</translation>
        </message>
        <message>
            <source>The transition refers to %1, which is neither a transition of %2 nor a variable.</source>
            <translation>该转换引用了 %1，但它既不是 %2 的转换，也不是变量。</translation>
        </message>
        <message>
            <source>The condition of this transition is not connected.</source>
            <translation>该转换的条件未连接。</translation>
        </message>
        <message>
            <source>The condition %1 is not an expression: %2</source>
            <translation>条件 %1 不是表达式：%2</translation>
        </message>
        <message>
            <source>%1 %2 is not a TIME literal or variable.</source>
            <translation>%1 %2 不是 TIME 常量或变量。</translation>
        </message>
        <message>
            <source>write e.g. T#5s</source>
            <translation>例如写成 T#5s</translation>
        </message>
        <message>
            <source>The maximum time</source>
            <translation>最长时间</translation>
        </message>
        <message>
            <source>The minimum time</source>
            <translation>最短时间</translation>
        </message>
        <message>
            <source>The duration</source>
            <translation>时间</translation>
        </message>
        <message>
            <source>%1 is a function written in SFC; a chart keeps its state, so it must be a program or a function block.</source>
            <translation>%1 是用 SFC 编写的函数；顺序功能图需要保持状态，所以它必须是程序或功能块。</translation>
        </message>
        <message>
            <source>Two steps are called %1.</source>
            <translation>有两个步都叫 %1。</translation>
        </message>
        <message>
            <source>The transition refers to step %1, which the chart does not have.</source>
            <translation>该转换引用了步 %1，但顺序功能图中没有该步。</translation>
        </message>
        <message>
            <source>This selection divergence needs at least two branches; it has %1.</source>
            <translation>该选择分支至少需要两个分支，现在只有 %1 个。</translation>
        </message>
        <message>
            <source>This simultaneous divergence needs at least two branches; it has %1.</source>
            <translation>该并行分支至少需要两个分支，现在只有 %1 个。</translation>
        </message>
        <message>
            <source>This selection convergence needs at least two branches; it joins %1.</source>
            <translation>该选择合并至少需要合并两个分支，现在只有 %1 个。</translation>
        </message>
        <message>
            <source>This simultaneous convergence needs at least two branches; it joins %1.</source>
            <translation>该并行合并至少需要合并两个分支，现在只有 %1 个。</translation>
        </message>
        <message>
            <source>The condition %1 is incomplete: something is missing at its end.</source>
            <translation>条件 %1 不完整：其末尾缺少内容。</translation>
        </message>
        <message>
            <source>The type of the value this loop carries cannot be told.</source>
            <translation>无法确定此环路传递的值的类型。</translation>
        </message>
        <message>
            <source>wire the loop through a variable of the type you mean</source>
            <translation>让环路经过一个所需类型的变量</translation>
        </message>
        <message>
            <source>Write one METHOD ... END_METHOD or one PROPERTY ... END_PROPERTY here, and nothing before or after it.</source>
            <translation>此处只写一个 METHOD ... END_METHOD 或一个 PROPERTY ... END_PROPERTY，前后不要有其他内容。</translation>
        </message>
        <message>
            <source>The text holds the control character U+%1, which a project file cannot keep; remove it.</source>
            <translation>文本中含有控制字符 U+%1，项目文件无法保存它；请将其删除。</translation>
        </message>
        <message>
            <source>%1 must implement the method %2 of %3.</source>
            <translation>%1 必须实现 %3 的方法 %2。</translation>
        </message>
        <message>
            <source>%1 must implement the GET of the property %2 of %3.</source>
            <translation>%1 必须实现 %3 的属性 %2 的 GET。</translation>
        </message>
        <message>
            <source>%1 must implement the SET of the property %2 of %3.</source>
            <translation>%1 必须实现 %3 的属性 %2 的 SET。</translation>
        </message>
        <message>
            <source>%1 implements %2, which is no interface of the project.</source>
            <translation>%1 实现了 %2，但它不是本项目中的接口。</translation>
        </message>
        <message>
            <source>This text must be one INTERFACE ... END_INTERFACE and nothing else.</source>
            <translation>此文本必须恰好是一个 INTERFACE ... END_INTERFACE，不能有其他内容。</translation>
        </message>
        <message>
            <source>%1 cannot override %2: it is FINAL.</source>
            <translation>%1 不能重写 %2：它是 FINAL。</translation>
        </message>
        <message>
            <source>%1 must implement the ABSTRACT %2, or be ABSTRACT itself.</source>
            <translation>%1 必须实现 ABSTRACT 的 %2，或者自身声明为 ABSTRACT。</translation>
        </message>
        <message>
            <source>%1 is a type of Beremiz's SVGHMI, which IEC Studio does not have: its variables are read as %2 and no HMI is shown.</source>
            <translation>%1 是 Beremiz SVGHMI 的类型，IEC Studio 没有 SVGHMI：这类变量按 %2 读取，不显示 HMI。</translation>
        </message>
        <message>
            <source>watch and write them in the watch pane instead</source>
            <translation>请改在监视窗格中查看和写入这些变量</translation>
        </message>
        <message>
            <source>The chart of %1 cannot be written as textual SFC (it is incomplete, or has macro steps, actions written in a step or conditions drawn as networks); it was left out.</source>
            <translation>%1 的图无法写成文本 SFC（图不完整，或含有宏步、写在步中的动作或画成网络的条件），已省略。</translation>
        </message>
        <message>
            <source>%1 of %2: IEC 61131-3 shifts bit strings only; as in CODESYS, its bits are shifted as those of a %3.</source>
            <translation>对 %2 使用 %1：IEC 61131-3 只允许移位位串；与 CODESYS 一样，按 %3 的位进行移位。</translation>
        </message>
        <message>
            <source>The file is not UTF-8: it was read as Windows-1252, the code page CoDeSys 2.3 writes, so that its umlauts and other special characters are kept.</source>
            <translation>该文件不是 UTF-8 编码：已按 Windows-1252（CoDeSys 2.3 使用的代码页）读取，以保留其中的变音字母和其他特殊字符。</translation>
        </message>
        <message>
            <source>%1 is a variable, not a constant: it has no value before the program runs.</source>
            <translation>%1 是变量，不是常量：程序运行之前它没有值。</translation>
        </message>
        <message>
            <source>declare it in VAR CONSTANT with an initial value</source>
            <translation>在 VAR CONSTANT 中声明它并给出初始值</translation>
        </message>
        <message>
            <source>CoDeSys 2.3 exported this %1 body in its own graphical form, which IEC Studio does not read; it is kept below as a comment. Export the POU from CoDeSys as PLCopen XML to open it as a diagram.</source>
            <translation>CoDeSys 2.3 以其自有的图形格式导出了此 %1 程序体，IEC Studio 无法读取；它作为注释保留在下方。请在 CoDeSys 中将该 POU 导出为 PLCopen XML，即可作为图表打开。</translation>
        </message>
    </context>
    <context>
        <name>iec::interp::Condition</name>
        <message>
            <source>The condition is nested too deeply.</source>
            <translation>条件嵌套太深。</translation>
        </message>
        <message>
            <source>A condition can only read variables and compare them; it cannot call anything.</source>
            <translation>条件只能读取并比较变量，不能调用任何东西。</translation>
        </message>
        <message>
            <source>There is no variable called %1 here.</source>
            <translation>这里没有名为 %1 的变量。</translation>
        </message>
        <message>
            <source>Text cannot be calculated with.</source>
            <translation>文本不能参与计算。</translation>
        </message>
        <message>
            <source>AND, OR, XOR and NOT need TRUE or FALSE here.</source>
            <translation>AND、OR、XOR 和 NOT 在这里需要 TRUE 或 FALSE。</translation>
        </message>
        <message>
            <source>The condition divides by zero.</source>
            <translation>条件中除以零。</translation>
        </message>
        <message>
            <source>The operator %1 cannot be used in a condition.</source>
            <translation>条件中不能使用运算符 %1。</translation>
        </message>
        <message>
            <source>This is not an expression: %1</source>
            <translation>这不是一个表达式：%1</translation>
        </message>
        <message>
            <source>The condition must be TRUE or FALSE, not a number or a text.</source>
            <translation>条件必须是 TRUE 或 FALSE，而不是数字或文本。</translation>
        </message>
    </context>
    <context>
        <name>iec::interp::Runtime</name>
        <message>
            <source>Integer division by zero.</source>
            <translation>整数除以零。</translation>
        </message>
        <message>
            <source>Array index out of range.</source>
            <translation>数组下标越界。</translation>
        </message>
        <message>
            <source>The text does not fit into the string variable.</source>
            <translation>文本超出字符串变量的容量。</translation>
        </message>
        <message>
            <source>The program ran too long in one cycle; is there an endless loop?</source>
            <translation>程序在一个周期内运行时间过长；是否有死循环？</translation>
        </message>
        <message>
            <source>Calls are nested too deeply.</source>
            <translation>调用嵌套太深。</translation>
        </message>
        <message>
            <source>The program cannot run (it did not compile).</source>
            <translation>程序无法运行（编译未通过）。</translation>
        </message>
        <message>
            <source>A value outside the subrange of its type was assigned.</source>
            <translation>赋给变量的值超出了其类型的子范围。</translation>
        </message>
        <message>
            <source>A pointer or reference that points nowhere (0) was used.</source>
            <translation>使用了指向空地址（0）的指针或引用。</translation>
        </message>
        <message>
            <source>A pointer that points outside the program's memory was used.</source>
            <translation>使用了指向程序内存之外的指针。</translation>
        </message>
        <message>
            <source>There is no variable called %1.</source>
            <translation>没有名为 %1 的变量。</translation>
        </message>
        <message>
            <source>%1 is out of the range of %2 (%3..%4).</source>
            <translation>%1 超出了 %2 的取值范围（%3..%4）。</translation>
        </message>
        <message>
            <source>%1 does not fit the %2 bits of %3.</source>
            <translation>%1 超出了 %3 的 %2 位。</translation>
        </message>
        <message>
            <source>'%1' is not a valid %2.</source>
            <translation>'%1' 不是有效的 %2 值。</translation>
        </message>
        <message>
            <source>The text is longer than the %1 characters of the string.</source>
            <translation>文本长度超过了字符串的 %1 个字符。</translation>
        </message>
        <message>
            <source>Only elementary variables and strings can be written.</source>
            <translation>只能写入基本类型变量和字符串。</translation>
        </message>
        <message>
            <source>%1 is out of the range of REAL (about ±3.4E38).</source>
            <translation>%1 超出了 REAL 的取值范围（约 ±3.4E38）。</translation>
        </message>
        <message>
            <source>%1 is out of the range of LREAL (about ±1.8E308).</source>
            <translation>%1 超出了 LREAL 的取值范围（约 ±1.8E308）。</translation>
        </message>
        <message>
            <source>The program halted.</source>
            <translation>程序已暂停。</translation>
        </message>
        <message>
            <source>A STRING cannot hold %1 (it holds the characters of Windows-1252); use a WSTRING.</source>
            <translation>STRING 无法容纳 %1（它只能容纳 Windows-1252 的字符）；请使用 WSTRING。</translation>
        </message>
    </context>
    <context>
        <name>iec::interp::Trace</name>
        <message>
            <source>%1 is a %2: only BOOL, numbers, bit strings, enumerations, times and dates can be traced. Trace its elements or members instead.</source>
            <translation>%1 是 %2：只能跟踪 BOOL、数值、位串、枚举、时间和日期。请改为跟踪它的元素或成员。</translation>
        </message>
    </context>
    <context>
        <name>iec::interp::TraceRecorder</name>
        <message>
            <source>There is no variable called %1.</source>
            <translation>没有名为 %1 的变量。</translation>
        </message>
        <message>
            <source>The trigger variable %1 is not a BOOL or number of the program; the trace records without a trigger.</source>
            <translation>触发变量 %1 不是程序中的 BOOL 或数值；跟踪将不带触发地记录。</translation>
        </message>
        <message>
            <source>The record condition is not an expression: %1</source>
            <translation>记录条件不是表达式：%1</translation>
        </message>
    </context>
    <context>
        <name>iec::model::AddDataTypeCommand</name>
        <message>
            <source>Add data type %1</source>
            <translation>添加数据类型 %1</translation>
        </message>
    </context>
    <context>
        <name>iec::model::AddPouCommand</name>
        <message>
            <source>Add POU %1</source>
            <translation>添加 POU %1</translation>
        </message>
    </context>
    <context>
        <name>iec::model::AddPouPartCommand</name>
        <message>
            <source>Add action %1</source>
            <translation>添加动作 %1</translation>
        </message>
        <message>
            <source>Add transition %1</source>
            <translation>添加转换 %1</translation>
        </message>
    </context>
    <context>
        <name>iec::model::AddVariableCommand</name>
        <message>
            <source>Add variable %1</source>
            <translation>添加变量 %1</translation>
        </message>
    </context>
    <context>
        <name>iec::model::ChangeDataTypeCommand</name>
        <message>
            <source>Change data type %1</source>
            <translation>修改数据类型 %1</translation>
        </message>
        <message>
            <source>Rename %1 to %2</source>
            <translation>将 %1 重命名为 %2</translation>
        </message>
    </context>
    <context>
        <name>iec::model::ChangeElementCommand</name>
        <message>
            <source>Change %1</source>
            <translation>修改 %1</translation>
        </message>
    </context>
    <context>
        <name>iec::model::ChangeVariableCommand</name>
        <message>
            <source>Change variable %1</source>
            <translation>修改变量 %1</translation>
        </message>
    </context>
    <context>
        <name>iec::model::ConnectCommand</name>
        <message>
            <source>Connect</source>
            <translation>连接</translation>
        </message>
    </context>
    <context>
        <name>iec::model::DisconnectCommand</name>
        <message>
            <source>Disconnect</source>
            <translation>断开连接</translation>
        </message>
    </context>
    <context>
        <name>iec::model::DuplicatePouCommand</name>
        <message>
            <source>Duplicate POU as %1</source>
            <translation>复制 POU 为 %1</translation>
        </message>
    </context>
    <context>
        <name>iec::model::InsertElementCommand</name>
        <message>
            <source>Insert %1</source>
            <translation>插入 %1</translation>
        </message>
    </context>
    <context>
        <name>iec::model::MoveElementsCommand</name>
        <message numerus="yes">
            <source>Move %n element(s)</source>
            <translation>
                <numerusform>移动 %n 个元素</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>iec::model::RemoveDataTypeCommand</name>
        <message>
            <source>Delete data type %1</source>
            <translation>删除数据类型 %1</translation>
        </message>
    </context>
    <context>
        <name>iec::model::RemoveElementCommand</name>
        <message>
            <source>Delete %1</source>
            <translation>删除 %1</translation>
        </message>
    </context>
    <context>
        <name>iec::model::RemovePouCommand</name>
        <message>
            <source>Delete POU %1</source>
            <translation>删除 POU %1</translation>
        </message>
    </context>
    <context>
        <name>iec::model::RemovePouPartCommand</name>
        <message>
            <source>Delete action %1</source>
            <translation>删除动作 %1</translation>
        </message>
        <message>
            <source>Delete transition %1</source>
            <translation>删除转换 %1</translation>
        </message>
    </context>
    <context>
        <name>iec::model::RemoveVariableCommand</name>
        <message>
            <source>Delete variable %1</source>
            <translation>删除变量 %1</translation>
        </message>
    </context>
    <context>
        <name>iec::model::RenamePouCommand</name>
        <message>
            <source>Rename %1 to %2</source>
            <translation>将 %1 重命名为 %2</translation>
        </message>
    </context>
    <context>
        <name>iec::model::RenamePouPartCommand</name>
        <message>
            <source>Rename %1 to %2</source>
            <translation>将 %1 重命名为 %2</translation>
        </message>
    </context>
    <context>
        <name>iec::model::SaveFile</name>
        <message>
            <source>the folder %1 does not exist</source>
            <translation>文件夹 %1 不存在</translation>
        </message>
        <message>
            <source>a folder of that name is in the way</source>
            <translation>已有同名的文件夹</translation>
        </message>
        <message>
            <source>the folder %1 is read-only, or you may not write in it</source>
            <translation>文件夹 %1 为只读，或您没有写入权限</translation>
        </message>
        <message>
            <source>the file is read-only</source>
            <translation>文件为只读</translation>
        </message>
        <message>
            <source>the disk is full</source>
            <translation>磁盘已满</translation>
        </message>
        <message>
            <source>the file would be larger than the system allows</source>
            <translation>文件将超过系统允许的大小</translation>
        </message>
        <message>
            <source>%1 was not saved: %2. The file on the disk is unchanged.</source>
            <translation>%1 未保存：%2。磁盘上的文件未改变。</translation>
        </message>
    </context>
    <context>
        <name>iec::model::SetBodyTextCommand</name>
        <message>
            <source>Edit text</source>
            <translation>编辑文本</translation>
        </message>
    </context>
    <context>
        <name>iec::model::SetInstancesCommand</name>
        <message>
            <source>Change configurations</source>
            <translation>更改配置</translation>
        </message>
    </context>
    <context>
        <name>iec::model::SetInterfaceCommand</name>
        <message>
            <source>Edit declarations</source>
            <translation>编辑声明</translation>
        </message>
    </context>
    <context>
        <name>iec::model::plcopen</name>
        <message>
            <source>It is not well-formed XML: %1.</source>
            <translation>它不是格式正确的 XML：%1。</translation>
        </message>
        <message>
            <source>It is XML with a &lt;%1&gt; root, not elements copied in IEC Studio.</source>
            <translation>它是根元素为 &lt;%1&gt; 的 XML，不是在 IEC Studio 中复制的元素。</translation>
        </message>
        <message>
            <source>It cannot be read: %1</source>
            <translation>无法读取：%1</translation>
        </message>
        <message>
            <source>It holds something that is not an element of a body.</source>
            <translation>其中包含不属于程序体元素的内容。</translation>
        </message>
    </context>
    <context>
        <name>iec::model::plcopen::Reader</name>
        <message>
            <source>The elements are nested too deeply; the content below is skipped.</source>
            <translation>元素嵌套过深；其下的内容被跳过。</translation>
        </message>
        <message>
            <source>The attribute %1="%2" of &lt;%3&gt; has an invalid value; it is kept as written.</source>
            <translation>&lt;%3&gt; 的属性 %1="%2" 的值无效；按原样保留。</translation>
        </message>
        <message>
            <source>&lt;%1&gt; lacks the required attribute '%2'.</source>
            <translation>&lt;%1&gt; 缺少必需的属性 '%2'。</translation>
        </message>
        <message>
            <source>&lt;%1&gt; lacks the required element &lt;%2&gt;.</source>
            <translation>&lt;%1&gt; 缺少必需的元素 &lt;%2&gt;。</translation>
        </message>
        <message>
            <source>Unknown attribute '%1' on &lt;%2&gt; is kept as it is.</source>
            <translation>&lt;%2&gt; 上的未知属性 '%1' 按原样保留。</translation>
        </message>
        <message>
            <source>Unknown attribute '%1' on &lt;%2&gt; is ignored.</source>
            <translation>&lt;%2&gt; 上的未知属性 '%1' 被忽略。</translation>
        </message>
        <message>
            <source>Unknown element &lt;%1&gt; in &lt;%2&gt; is kept as it is.</source>
            <translation>&lt;%2&gt; 中的未知元素 &lt;%1&gt; 按原样保留。</translation>
        </message>
        <message>
            <source>Unknown element &lt;%1&gt; in &lt;%2&gt; is ignored.</source>
            <translation>&lt;%2&gt; 中的未知元素 &lt;%1&gt; 被忽略。</translation>
        </message>
        <message>
            <source>A declaration in addData is nested too deeply to read; it is kept as it is.</source>
            <translation>addData 中的声明嵌套过深，无法读取；按原样保留。</translation>
        </message>
        <message>
            <source>&lt;%1&gt; names no data type.</source>
            <translation>&lt;%1&gt; 没有指定数据类型。</translation>
        </message>
        <message>
            <source>The data type &lt;%1&gt; is not in the PLCopen schema; it is kept by name.</source>
            <translation>数据类型 &lt;%1&gt; 不属于 PLCopen 模式；按名称保留。</translation>
        </message>
        <message>
            <source>The namespace '%1' is not PLCopen TC6 XML 2.01; the file is read anyway.</source>
            <translation>命名空间 '%1' 不是 PLCopen TC6 XML 2.01；仍然读取该文件。</translation>
        </message>
        <message>
            <source>The file is not well-formed XML: %1.</source>
            <translation>该文件不是格式正确的 XML：%1。</translation>
        </message>
        <message>
            <source>The root element is &lt;%1&gt;, not &lt;project&gt;: this is not a PLCopen XML file.</source>
            <translation>根元素是 &lt;%1&gt; 而不是 &lt;project&gt;：这不是 PLCopen XML 文件。</translation>
        </message>
        <message>
            <source>Cannot open %1: %2.</source>
            <translation>无法打开 %1：%2。</translation>
        </message>
        <message>
            <source>This &lt;action&gt; has no localId; it was given %1.</source>
            <translation>该 &lt;action&gt; 没有 localId，已为其分配 %1。</translation>
        </message>
        <message>
            <source>This &lt;action&gt; has no position; it is placed at (0, 0).</source>
            <translation>该 &lt;action&gt; 没有位置，已放置在 (0, 0)。</translation>
        </message>
        <message>
            <source>&lt;pouInstance&gt; names its POU with 'type'; PLCopen calls it 'typeName', which it is written as.</source>
            <translation>&lt;pouInstance&gt; 用 'type' 指定其 POU；PLCopen 中应为 'typeName'，保存时将写为 'typeName'。</translation>
        </message>
        <message>
            <source>creationDateTime '%1' has a space where XML wants a 'T'; it is written as '%2'.</source>
            <translation>creationDateTime '%1' 中应为 'T' 的位置是空格，保存时将写为 '%2'。</translation>
        </message>
        <message>
            <source>Characters XML does not allow (control characters, U+FFFE or U+FFFF) were left out of the file, %1 in all, so that the project is saved as valid XML.</source>
            <translation>文件中含有 XML 不允许的字符（控制字符、U+FFFE 或 U+FFFF），共 %1 个，已被略去，以便项目保存为有效的 XML。</translation>
        </message>
        <message>
            <source>&lt;%1&gt; has the attribute %2 more than once; the first is kept.</source>
            <translation>&lt;%1&gt; 多次出现属性 %2；保留第一个。</translation>
        </message>
        <message>
            <source>&lt;%1&gt; in &lt;%2&gt; is more than the file format allows there; it is kept as it is, but not read.</source>
            <translation>&lt;%2&gt; 中的 &lt;%1&gt; 超出了文件格式在此处允许的数量；它按原样保留，但不会被读取。</translation>
        </message>
        <message>
            <source>&lt;%1&gt; in &lt;%2&gt; is more than the file format allows there; it is ignored.</source>
            <translation>&lt;%2&gt; 中的 &lt;%1&gt; 超出了文件格式在此处允许的数量；已忽略。</translation>
        </message>
    </context>
    <context>
        <name>main</name>
        <message>
            <source>Open Project</source>
            <translation>打开项目</translation>
        </message>
    </context>
</TS>
