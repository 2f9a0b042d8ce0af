<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>NameRules</name>
    <message>
        <source>Enter a name.</source>
        <translation>请输入名称。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not an IEC identifier: use letters, digits and single underscores, starting with a letter or an underscore and not ending with an underscore.</source>
        <translation>&quot;%1&quot; 不是 IEC 标识符：只能使用字母、数字和单个下划线，以字母或下划线开头，且不能以下划线结尾。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is a reserved word of IEC 61131-3.</source>
        <translation>&quot;%1&quot; 是 IEC 61131-3 的保留字。</translation>
    </message>
    <message>
        <source>A POU or data type named &quot;%1&quot; exists already.</source>
        <translation>名为 &quot;%1&quot; 的 POU 或数据类型已存在。</translation>
    </message>
    <message>
        <source>This POU has an action or transition named &quot;%1&quot; already.</source>
        <translation>此 POU 已有名为 &quot;%1&quot; 的动作或转换。</translation>
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
        <translation>该 POU 已不存在。</translation>
    </message>
    <message>
        <source>The item does not exist any more.</source>
        <translation>该项已不存在。</translation>
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
    <name>iec::app::BuildController</name>
    <message>
        <source>%1 Hint: %2</source>
        <translation>%1 提示：%2</translation>
    </message>
</context>
<context>
    <name>iec::app::DocumentArea</name>
    <message>
        <source>This body is written in %1. Its editor is not available in this version; the body is kept unchanged when the project is saved.</source>
        <translation>此程序体使用 %1 编写。本版本尚未提供该语言的编辑器；保存项目时程序体保持不变。</translation>
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
        <source>PLCopen XML projects (*.xml);;All files (*)</source>
        <translation>PLCopen XML 项目 (*.xml);;所有文件 (*)</translation>
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
</context>
<context>
    <name>iec::editors::DataTypeEditor</name>
    <message>
        <source>Name:</source>
        <translation>名称：</translation>
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
</context>
<context>
    <name>iec::editors::DataTypeValidator</name>
    <message>
        <source>A POU or data type named &quot;%1&quot; exists already.</source>
        <translation>名为 &quot;%1&quot; 的 POU 或数据类型已存在。</translation>
    </message>
    <message>
        <source>A structure needs at least one member.</source>
        <translation>结构体至少需要一个成员。</translation>
    </message>
    <message>
        <source>There is a member named &quot;%1&quot; already.</source>
        <translation>已有名为 &quot;%1&quot; 的成员。</translation>
    </message>
    <message>
        <source>An enumeration needs at least one value.</source>
        <translation>枚举至少需要一个值。</translation>
    </message>
    <message>
        <source>The value &quot;%1&quot; is listed already.</source>
        <translation>值 &quot;%1&quot; 已列出。</translation>
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
        <source>&quot;%1&quot; is not a type.</source>
        <translation>&quot;%1&quot; 不是类型。</translation>
    </message>
    <message>
        <source>A type cannot contain itself.</source>
        <translation>类型不能包含自身。</translation>
    </message>
    <message>
        <source>Unknown type &quot;%1&quot;.</source>
        <translation>未知类型 &quot;%1&quot;。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a valid initial value.</source>
        <translation>&quot;%1&quot; 不是有效的初始值。</translation>
    </message>
    <message>
        <source>Enter a name.</source>
        <translation>请输入名称。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not an IEC identifier: use letters, digits and single underscores, starting with a letter or an underscore and not ending with an underscore.</source>
        <translation>&quot;%1&quot; 不是 IEC 标识符：只能使用字母、数字和单个下划线，以字母或下划线开头，且不能以下划线结尾。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is a reserved word of IEC 61131-3.</source>
        <translation>&quot;%1&quot; 是 IEC 61131-3 的保留字。</translation>
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
        <translation>删除</translation>
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
</context>
<context>
    <name>iec::editors::DeclarationRows</name>
    <message>
        <source>&quot;%1&quot; is not a variable class.</source>
        <translation>&quot;%1&quot; 不是变量类别。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a data type.</source>
        <translation>&quot;%1&quot; 不是数据类型。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not an initial value for %2.</source>
        <translation>&quot;%1&quot; 不是 %2 的初始值。</translation>
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
        <source>&quot;%1&quot; is not a valid name: use letters, digits and single underscores, and no keyword.</source>
        <translation>&quot;%1&quot; 不是有效的名称：请使用字母、数字和单个下划线，且不能是关键字。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not an address such as %IX0.0, %QW3 or %MD10.</source>
        <translation>&quot;%1&quot; 不是地址(例如 %IX0.0、%QW3 或 %MD10)。</translation>
    </message>
    <message>
        <source>%1 is declared twice.</source>
        <translation>%1 被声明了两次。</translation>
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
        <translation>删除</translation>
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
    <name>iec::model::SetBodyTextCommand</name>
    <message>
        <source>Edit text</source>
        <translation>编辑文本</translation>
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
    <name>iec::model::plcopen::Reader</name>
    <message>
        <source>The elements are nested too deeply; the content below is skipped.</source>
        <translation>元素嵌套过深；其下的内容被跳过。</translation>
    </message>
    <message>
        <source>The attribute %1=&quot;%2&quot; of &lt;%3&gt; has an invalid value; it is kept as written.</source>
        <translation>&lt;%3&gt; 的属性 %1=&quot;%2&quot; 的值无效；按原样保留。</translation>
    </message>
    <message>
        <source>&lt;%1&gt; lacks the required attribute &apos;%2&apos;.</source>
        <translation>&lt;%1&gt; 缺少必需的属性 &apos;%2&apos;。</translation>
    </message>
    <message>
        <source>&lt;%1&gt; lacks the required element &lt;%2&gt;.</source>
        <translation>&lt;%1&gt; 缺少必需的元素 &lt;%2&gt;。</translation>
    </message>
    <message>
        <source>Unknown attribute &apos;%1&apos; on &lt;%2&gt; is kept as it is.</source>
        <translation>&lt;%2&gt; 上的未知属性 &apos;%1&apos; 按原样保留。</translation>
    </message>
    <message>
        <source>Unknown attribute &apos;%1&apos; on &lt;%2&gt; is ignored.</source>
        <translation>&lt;%2&gt; 上的未知属性 &apos;%1&apos; 被忽略。</translation>
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
        <source>The namespace &apos;%1&apos; is not PLCopen TC6 XML 2.01; the file is read anyway.</source>
        <translation>命名空间 &apos;%1&apos; 不是 PLCopen TC6 XML 2.01；仍然读取该文件。</translation>
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
</context>
<context>
    <name>iec::model::plcopen::Writer</name>
    <message>
        <source>Cannot save %1: %2.</source>
        <translation>无法保存 %1：%2。</translation>
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
