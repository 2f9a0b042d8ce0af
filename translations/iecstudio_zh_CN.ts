<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>iec::app::MainWindow</name>
    <message>
        <source>IEC Studio</source>
        <translation>IEC Studio</translation>
    </message>
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
        <source>&amp;Undo</source>
        <translation>撤销(&amp;U)</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>重做(&amp;R)</translation>
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
        <source>Open a POU from the project tree to edit it.</source>
        <translation>在项目树中打开一个程序组织单元(POU)进行编辑。</translation>
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
    <name>iec::model::AddPouCommand</name>
    <message>
        <source>Add POU %1</source>
        <translation>添加 POU %1</translation>
    </message>
</context>
<context>
    <name>iec::model::RenamePouCommand</name>
    <message>
        <source>Rename %1 to %2</source>
        <translation>将 %1 重命名为 %2</translation>
    </message>
</context>
</TS>
