<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en">
    <context>
        <name>taiwa::ui::FileActions</name>
        <message numerus="yes">
            <source>Imported %1: %n turned profile(s)</source>
            <translation>
                <numerusform>Imported %1: %n turned profile</numerusform>
                <numerusform>Imported %1: %n turned profiles</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>The verification found %n faults (the first: %1).</source>
            <translation>
                <numerusform>The verification found %n fault (the first: %1).</numerusform>
                <numerusform>The verification found %n faults (the first: %1).</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::NcView</name>
        <message numerus="yes">
            <source>%n block(s)</source>
            <translation>
                <numerusform>%n block</numerusform>
                <numerusform>%n blocks</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::StationWindow</name>
        <message numerus="yes">
            <source>%n problem(s) in other units</source>
            <translation>
                <numerusform>%n problem in other units</numerusform>
                <numerusform>%n problems in other units</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%1 is also open in %n other window(s): a save here asks before it overwrites what another window saved.</source>
            <translation>
                <numerusform>%1 is also open in %n other window: a save here asks before it overwrites what another window saved.</numerusform>
                <numerusform>%1 is also open in %n other windows: a save here asks before it overwrites what another window saved.</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::StepPanel</name>
        <message numerus="yes">
            <source>%n step(s), %1 min, %2 tool change(s) (updating…)</source>
            <translation>
                <numerusform>%n step, %1 min, %2 tool change (updating…)</numerusform>
                <numerusform>%n steps, %1 min, %2 tool changes (updating…)</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n step(s), %1 min, %2 tool change(s)</source>
            <translation>
                <numerusform>%n step, %1 min, %2 tool change</numerusform>
                <numerusform>%n steps, %1 min, %2 tool changes</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>taiwa::ui::ToolLibraryDialog</name>
        <message numerus="yes">
            <source>%1 — %n tool(s)</source>
            <translation>
                <numerusform>%1 — %n tool</numerusform>
                <numerusform>%1 — %n tools</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>This changes %n step(s) of the open job:</source>
            <translation>
                <numerusform>This changes %n step of the open job:</numerusform>
                <numerusform>This changes %n steps of the open job:</numerusform>
            </translation>
        </message>
    </context>
</TS>
