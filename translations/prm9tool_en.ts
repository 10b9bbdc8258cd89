<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_US">
    <context>
        <name>CanBusDialog</name>
        <message numerus="yes">
            <source>%n node(s) answered.</source>
            <translation>
                <numerusform>%n node answered.</numerusform>
                <numerusform>%n nodes answered.</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n of them PRM9 valve(s).</source>
            <translation>
                <numerusform>%n of them a PRM9 valve.</numerusform>
                <numerusform>%n of them PRM9 valves.</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>CompareDialog</name>
        <message numerus="yes">
            <source>%n parameter(s) differ</source>
            <translation>
                <numerusform>%n parameter differs</numerusform>
                <numerusform>%n parameters differ</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n parameter(s) only on one side</source>
            <translation>
                <numerusform>%n parameter only on one side</numerusform>
                <numerusform>%n parameters only on one side</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n parameter(s) not on the valve, not compared</source>
            <translation>
                <numerusform>%n parameter not on the valve, not compared</numerusform>
                <numerusform>%n parameters not on the valve, not compared</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n shown</source>
            <translation>
                <numerusform>%n shown</numerusform>
                <numerusform>%n shown</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>Write %n ticked value(s) into the valve</source>
            <translation>
                <numerusform>Write %n ticked value into the valve</numerusform>
                <numerusform>Write %n ticked values into the valve</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>Take %n ticked value(s) into the document</source>
            <translation>
                <numerusform>Take %n ticked value into the document</numerusform>
                <numerusform>Take %n ticked values into the document</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>Copy %n ticked value(s) into “{0}”</source>
            <translation>
                <numerusform>Copy %n ticked value into “{0}”</numerusform>
                <numerusform>Copy %n ticked values into “{0}”</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>CompareWorkflow</name>
        <message numerus="yes">
            <source>%n value(s) taken from the history</source>
            <translation>
                <numerusform>%n value taken from the history</numerusform>
                <numerusform>%n values taken from the history</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>FileWorkflow</name>
        <message numerus="yes">
            <source>“{0}” was opened; %n warning(s) were found.</source>
            <translation>
                <numerusform>“{0}” was opened; %n warning was found.</numerusform>
                <numerusform>“{0}” was opened; %n warnings were found.</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>(marked: %n rule(s) broken)</source>
            <translation>
                <numerusform>(marked: %n rule broken)</numerusform>
                <numerusform>(marked: %n rules broken)</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>… and %n more problem(s).</source>
            <translation>
                <numerusform>… and %n more problem.</numerusform>
                <numerusform>… and %n more problems.</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n more problem(s) in the details.</source>
            <translation>
                <numerusform>%n more problem in the details.</numerusform>
                <numerusform>%n more problems in the details.</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>HistoryTableModel</name>
        <message numerus="yes">
            <source>%n more</source>
            <translation>
                <numerusform>%n more</numerusform>
                <numerusform>%n more</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>HistoryWindow</name>
        <message numerus="yes">
            <source>%n record(s) in {0}</source>
            <translation>
                <numerusform>%n record in {0}</numerusform>
                <numerusform>%n records in {0}</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>LssPanel</name>
        <message numerus="yes">
            <source>%n device(s) without a node ID.</source>
            <translation>
                <numerusform>%n device without a node ID.</numerusform>
                <numerusform>%n devices without a node ID.</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>MainStatusBar</name>
        <message numerus="yes">
            <source>%n sample(s) lost</source>
            <translation>
                <numerusform>%n sample lost</numerusform>
                <numerusform>%n samples lost</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>OnlineDiffDialog</name>
        <message numerus="yes">
            <source>%n value(s) in the document differ from the valve.</source>
            <translation>
                <numerusform>%n value in the document differs from the valve.</numerusform>
                <numerusform>%n values in the document differ from the valve.</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>RestartVerifier</name>
        <message numerus="yes">
            <source>The last upload wrote %n parameter(s): {0}. The valve is restarted, then its parameters are read back and compared with the document: this shows that it keeps them through a restart, as after a power loss.</source>
            <translation>
                <numerusform>The last upload wrote %n parameter: {0}. The valve is restarted, then its parameters are read back and compared with the document: this shows that it keeps them through a restart, as after a power loss.</numerusform>
                <numerusform>The last upload wrote %n parameters: {0}. The valve is restarted, then its parameters are read back and compared with the document: this shows that it keeps them through a restart, as after a power loss.</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n parameter(s) of the last upload read back unchanged at {0}: {1}</source>
            <translation>
                <numerusform>%n parameter of the last upload read back unchanged at {0}: {1}</numerusform>
                <numerusform>%n parameters of the last upload read back unchanged at {0}: {1}</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>After the restart the valve reads back %n value(s) of the last upload otherwise: it did not keep them ({0}). It works with the values read back now (expected → read back below); the document still holds the uploaded values and the history records the differences. Edits no longer go to the valve: upload the document again, or download the valve's values.</source>
            <translation>
                <numerusform>After the restart the valve reads back %n value of the last upload otherwise: it did not keep it ({0}). It works with the value read back now (expected → read back below); the document still holds the uploaded value and the history records the difference. Edits no longer go to the valve: upload the document again, or download the valve's values.</numerusform>
                <numerusform>After the restart the valve reads back %n values of the last upload otherwise: it did not keep them ({0}). It works with the values read back now (expected → read back below); the document still holds the uploaded values and the history records the differences. Edits no longer go to the valve: upload the document again, or download the valve's values.</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>ValveUpload</name>
        <message numerus="yes">
            <source>The document changes %n Expert-level value(s) of the valve ({0}), which the Basic access level cannot edit (controllers, linearizations, monitoring). Send them anyway?</source>
            <translation>
                <numerusform>The document changes %n Expert-level value of the valve ({0}), which the Basic access level cannot edit (controllers, linearizations, monitoring). Send it anyway?</numerusform>
                <numerusform>The document changes %n Expert-level values of the valve ({0}), which the Basic access level cannot edit (controllers, linearizations, monitoring). Send them anyway?</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n parameter(s) written, verified and stored at {0}</source>
            <translation>
                <numerusform>%n parameter written, verified and stored at {0}</numerusform>
                <numerusform>%n parameters written, verified and stored at {0}</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n parameter(s) written, verified and stored again at {0}: the valve already held them</source>
            <translation>
                <numerusform>%n parameter written, verified and stored again at {0}: the valve already held it</numerusform>
                <numerusform>%n parameters written, verified and stored again at {0}: the valve already held them</numerusform>
            </translation>
        </message>
    </context>
</TS>
