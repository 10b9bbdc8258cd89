<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
    <context>
        <name>BlockDialog</name>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/base.py" line="211" />
            <source>Read only: %1 (View → Access level)</source>
            <translation>Nur lesbar: %1 (Ansicht → Berechtigungsstufe)</translation>
        </message>
    </context>
    <context>
        <name>CanopenWindow</name>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="154" />
            <source>CANopen</source>
            <translation>CANopen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="157" />
            <source>The valve reads its two rotary switches at power-up only; the marked rows are the positions it read at its last start. Terminator, node ID and bit rate set here are stored in the valve and take effect after the next restart.</source>
            <translation>Das Ventil liest seine beiden Drehschalter nur beim Einschalten; die markierten Zeilen sind die beim letzten Start gelesenen Stellungen. Hier eingestellter Abschlusswiderstand, Node-ID und Baudrate werden im Ventil gespeichert und nach dem nächsten Neustart wirksam.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="162" />
            <source>Interface / bit-rate switch</source>
            <translation>Schalter Schnittstelle / Baudrate</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="163" />
            <source>Node-ID switch</source>
            <translation>Schalter Node-ID</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="164" />
            <source>Settings made by software (USB)</source>
            <translation>Einstellungen per Software (USB)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="166" />
            <location filename="../prm9tool/views/canopen_window.py" line="168" />
            <source>Position</source>
            <translation>Stellung</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="166" />
            <source>Interface / bit rate</source>
            <translation>Schnittstelle / Baudrate</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="166" />
            <source>Terminator</source>
            <translation>Abschlusswiderstand</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="168" />
            <source>Node ID</source>
            <translation>Node-ID</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="169" />
            <source>CAN terminator 120 Ω</source>
            <translation>CAN-Abschlusswiderstand 120 Ω</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="170" />
            <source>Node ID (node switch at 0)</source>
            <translation>Node-ID (Node-Schalter auf 0)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="171" />
            <source>Bit rate (node switch at 0)</source>
            <translation>Baudrate (Node-Schalter auf 0)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="172" />
            <location filename="../prm9tool/views/canopen_window.py" line="187" />
            <location filename="../prm9tool/views/canopen_window.py" line="292" />
            <source>on</source>
            <translation>ein</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="182" />
            <source>CANopen off, analog setpoint only</source>
            <translation>CANopen aus, nur analoger Sollwert</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="184" />
            <source>reserved (as position 0)</source>
            <translation>reserviert (wie Stellung 0)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="189" />
            <source>off (on by software)</source>
            <translation>aus (per Software ein)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="190" />
            <source>CANopen, %1</source>
            <translation>CANopen, %1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="195" />
            <source>set by software: 1 … 127 (below)</source>
            <translation>per Software: 1 … 127 (unten)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="197" />
            <source>LSS, automatic bit rate</source>
            <translation>LSS, automatische Baudrate</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="225" />
            <source>Position read by the valve at its last power-up</source>
            <translation>Beim letzten Einschalten vom Ventil gelesene Stellung</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="240" />
            <source>The node-ID switch is not at 0: the switch sets the node ID.</source>
            <translation>Der Node-ID-Schalter steht nicht auf 0: der Schalter legt die Node-ID fest.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="260" />
            <source>This valve type has no CANopen interface (no -CA in the type key).</source>
            <translation>Dieser Ventiltyp hat keine CANopen-Schnittstelle (kein -CA im Typschlüssel).</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="263" />
            <source>Offline: the switch positions are unknown. Settings changed here go into the document; upload it to the valve and restart the valve.</source>
            <translation>Offline: die Schalterstellungen sind unbekannt. Hier geänderte Einstellungen gehen in das Dokument; laden Sie es in das Ventil und starten Sie das Ventil neu.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="267" />
            <source>Reading the switch positions from the valve …</source>
            <translation>Schalterstellungen werden aus dem Ventil gelesen …</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="269" />
            <source>Switch positions read from the valve at its last power-up.</source>
            <translation>Beim letzten Einschalten aus dem Ventil gelesene Schalterstellungen.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="272" />
            <source>With the node-ID switch at 0 or 1 the terminator follows the software setting below, whatever the interface switch says.</source>
            <translation>Steht der Node-ID-Schalter auf 0 oder 1, folgt der Abschlusswiderstand der Software-Einstellung unten, unabhängig vom Schnittstellenschalter.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="286" />
            <source>After the next restart the valve uses:</source>
            <translation>Nach dem nächsten Neustart verwendet das Ventil:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="288" />
            <source>The valve uses:</source>
            <translation>Das Ventil verwendet:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="290" />
            <source>CANopen off (analog setpoint only).</source>
            <translation>CANopen aus (nur analoger Sollwert).</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="292" />
            <source>off</source>
            <translation>aus</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="294" />
            <source>node ID %1, %2, terminator %3.</source>
            <translation>Node-ID %1, %2, Abschlusswiderstand %3.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="322" />
            <source>Changed in the document. Upload it to the valve; the change takes effect after the valve restarts.</source>
            <translation>Im Dokument geändert. Laden Sie es in das Ventil; die Änderung wird nach einem Neustart des Ventils wirksam.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="337" />
            <source>Written to the valve and stored. The change takes effect after the valve restarts (Valve → Restart valve).</source>
            <translation>In das Ventil geschrieben und gespeichert. Die Änderung wird nach einem Neustart des Ventils wirksam (Ventil → Ventil neu starten).</translation>
        </message>
    </context>
    <context>
        <name>ChangePasswordDialog</name>
        <message>
            <location filename="../prm9tool/views/access_dialog.py" line="76" />
            <source>Change Expert password</source>
            <translation>Expertenpasswort ändern</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/access_dialog.py" line="87" />
            <source>Current password:</source>
            <translation>Aktuelles Passwort:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/access_dialog.py" line="88" />
            <source>New password:</source>
            <translation>Neues Passwort:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/access_dialog.py" line="89" />
            <source>Repeat new password:</source>
            <translation>Neues Passwort wiederholen:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/access_dialog.py" line="97" />
            <source>The current password is wrong.</source>
            <translation>Das aktuelle Passwort ist falsch.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/access_dialog.py" line="99" />
            <source>The new password must have at least {0} characters.</source>
            <translation>Das neue Passwort muss mindestens {0} Zeichen haben.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/access_dialog.py" line="101" />
            <source>The two new passwords differ.</source>
            <translation>Die beiden neuen Passwörter stimmen nicht überein.</translation>
        </message>
    </context>
    <context>
        <name>ChannelPanel</name>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="54" />
            <source>Measuring points</source>
            <translation>Messpunkte</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="91" />
            <source>At most three measuring points: {0} replaces {1}.</source>
            <translation>Höchstens drei Messpunkte: {0} ersetzt {1}.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="109" />
            <source>At most three measuring points can be recorded at once. Switch one off before adding {0}.</source>
            <translation>Höchstens drei Messpunkte können gleichzeitig aufgezeichnet werden. Schalten Sie einen ab, bevor Sie {0} hinzufügen.</translation>
        </message>
    </context>
    <context>
        <name>ControlPanel</name>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="229" />
            <source>Recording</source>
            <translation>Aufzeichnung</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="230" />
            <source>Interval</source>
            <translation>Intervall</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="231" />
            <source>Time window</source>
            <translation>Zeitfenster</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="232" />
            <source>Start</source>
            <translation>Start</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="233" />
            <source>Stop</source>
            <translation>Stopp</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="235" />
            <source>Trigger</source>
            <translation>Trigger</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="237" />
            <source>Roll (no trigger)</source>
            <translation>Rollen (ohne Trigger)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="238" />
            <source>Auto</source>
            <translation>Auto</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="239" />
            <source>Normal</source>
            <translation>Normal</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="240" />
            <source>Single</source>
            <translation>Einzeln</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="241" />
            <source>Rising edge</source>
            <translation>Steigende Flanke</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="242" />
            <source>Falling edge</source>
            <translation>Fallende Flanke</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="247" />
            <source>Pre-trigger</source>
            <translation>Vortrigger</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="248" />
            <source>Trigger level in the trigger channel's unit</source>
            <translation>Triggerpegel in der Einheit des Triggerkanals</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="249" />
            <source>Display and export</source>
            <translation>Anzeige und Export</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="250" />
            <source>Cursors A/B</source>
            <translation>Cursor A/B</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="251" />
            <source>Same scale per unit</source>
            <translation>Gleiche Skala je Einheit</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="253" />
            <source>Autoscaled channels with the same unit share one scale</source>
            <translation>Automatisch skalierte Kanäle mit gleicher Einheit teilen eine Skala</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="255" />
            <source>Export CSV</source>
            <translation>CSV exportieren</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="258" />
            <source>Visible window…</source>
            <translation>Sichtbares Fenster…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="259" />
            <source>Whole recording…</source>
            <translation>Gesamte Aufzeichnung…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="260" />
            <source>Export PNG…</source>
            <translation>PNG exportieren…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="267" />
            <source>Resume</source>
            <translation>Fortsetzen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="267" />
            <source>Pause</source>
            <translation>Pause</translation>
        </message>
    </context>
    <context>
        <name>ControllerDialog</name>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/controller.py" line="118" />
            <source>No simulation available.</source>
            <translation>Keine Simulation verfügbar.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/controller.py" line="132" />
            <source>Simulation failed: %1</source>
            <translation>Simulation fehlgeschlagen: %1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/controller.py" line="138" />
            <source>setpoint</source>
            <translation>Sollwert</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/controller.py" line="142" />
            <source>applied values</source>
            <translation>übernommene Werte</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/controller.py" line="143" />
            <source>actual value</source>
            <translation>Istwert</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/controller.py" line="149" />
            <source>Time (ms)</source>
            <translation>Zeit (ms)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/controller.py" line="149" />
            <source>Value (%)</source>
            <translation>Wert (%)</translation>
        </message>
    </context>
    <context>
        <name>CurrentDitherDialog</name>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/current_dither.py" line="47" />
            <source>Nominal coil current CURNORM: %1 mA — no limit may exceed it.</source>
            <translation>Nennstrom der Spule CURNORM: %1 mA – keine Grenze darf ihn überschreiten.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/current_dither.py" line="59" />
            <source>coil %1</source>
            <translation>Spule %1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/current_dither.py" line="60" />
            <source>limit %1</source>
            <translation>Grenze %1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/current_dither.py" line="64" />
            <source>Coil current (mA)</source>
            <translation>Spulenstrom (mA)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/current_dither.py" line="66" />
            <source>Coil current (mA), coil B downwards</source>
            <translation>Spulenstrom (mA), Spule B nach unten</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/current_dither.py" line="67" />
            <source>Time (ms)</source>
            <translation>Zeit (ms)</translation>
        </message>
    </context>
    <context>
        <name>CursorPanel</name>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="68" />
            <source>Cursors</source>
            <translation>Cursor</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="94" />
            <source>Switch the cursors on to measure.</source>
            <translation>Schalten Sie die Cursor zum Messen ein.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="97" />
            <source>Δt = {0}    1/Δt = {1}</source>
            <translation>Δt = {0}    1/Δt = {1}</translation>
        </message>
    </context>
    <context>
        <name>CurveEditor</name>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/linearization.py" line="63" />
            <source>1:1</source>
            <translation>1:1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/linearization.py" line="65" />
            <source>characteristic</source>
            <translation>Kennlinie</translation>
        </message>
    </context>
    <context>
        <name>DiagramBlock</name>
        <message>
            <location filename="../prm9tool/views/diagram/scene.py" line="107" />
            <source>spool position (LVDT)</source>
            <translation>Schieberposition (LVDT)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="110" />
            <source>Setpoint input</source>
            <translation>Sollwerteingang</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="115" />
            <source>Threshold</source>
            <translation>Schwelle</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="120" />
            <source>Gain &amp; offset</source>
            <translation>Verstärkung &amp; Offset</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="127" />
            <source>Linearization</source>
            <translation>Linearisierung</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="132" />
            <source>Ramps</source>
            <translation>Rampen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="138" />
            <source>Deviation gain &amp; offset</source>
            <translation>Abweichung: Verstärkung &amp; Offset</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="145" />
            <source>Process PIDT1</source>
            <translation>Prozessregler PIDT1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="152" />
            <source>External sensor</source>
            <translation>Externer Sensor</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="159" />
            <source>Sensor offset &amp; gain</source>
            <translation>Sensor: Offset &amp; Verstärkung</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="166" />
            <source>Sensor linearization</source>
            <translation>Sensor-Linearisierung</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="175" />
            <source>Position PIDT1</source>
            <translation>Lageregler PIDT1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="182" />
            <source>Current limiter</source>
            <translation>Strombegrenzung</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="187" />
            <source>Dither</source>
            <translation>Dither</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="188" />
            <source>Valve</source>
            <translation>Ventil</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="198" />
            <source>CANopen</source>
            <translation>CANopen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="203" />
            <source>Supply</source>
            <translation>Versorgung</translation>
        </message>
    </context>
    <context>
        <name>DiagramSummary</name>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="40" />
            <location filename="../prm9tool/views/diagram/summary.py" line="126" />
            <source>Polarity: %1</source>
            <translation>Polarität: %1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="45" />
            <source>Threshold %1</source>
            <translation>Schwelle %1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="56" />
            <location filename="../prm9tool/views/diagram/summary.py" line="133" />
            <source>Gain %1</source>
            <translation>Verstärkung %1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="59" />
            <location filename="../prm9tool/views/diagram/summary.py" line="132" />
            <source>Offset %1</source>
            <translation>Offset %1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="69" />
            <source>9-point curve on</source>
            <translation>9-Punkt-Kennlinie ein</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="71" />
            <source>off (1:1)</source>
            <translation>aus (1:1)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="96" />
            <source>Coil %1: %2</source>
            <translation>Spule %1: %2</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="106" />
            <source>Amplitude %1</source>
            <translation>Amplitude %1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="107" />
            <source>Frequency %1</source>
            <translation>Frequenz %1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="115" />
            <source>coils A and B</source>
            <translation>Spulen A und B</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="116" />
            <source>coil A only</source>
            <translation>nur Spule A</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="117" />
            <source>coil B only</source>
            <translation>nur Spule B</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="139" />
            <source>Voltage, temperature</source>
            <translation>Spannung, Temperatur</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="140" />
            <source>(live values)</source>
            <translation>(Live-Werte)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="146" />
            <source>Node ID %1 (switch 0)</source>
            <translation>Node-ID %1 (Schalter 0)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="149" />
            <source>Terminator %1</source>
            <translation>Abschlusswiderstand %1</translation>
        </message>
    </context>
    <context>
        <name>DiagramView</name>
        <message>
            <location filename="../prm9tool/views/diagram/view.py" line="223" />
            <source>Values measured by the valve; see the red measuring points.</source>
            <translation>Vom Ventil gemessene Werte; siehe die roten Messpunkte.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/view.py" line="227" />
            <source>Click to edit: %1</source>
            <translation>Zum Bearbeiten klicken: %1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/view.py" line="239" />
            <source>(View → Access level)</source>
            <translation>(Ansicht → Berechtigungsstufe)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/view.py" line="243" />
            <source>Online, the valve type is that of the connected valve.</source>
            <translation>Online ist der Ventiltyp der des angeschlossenen Ventils.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/view.py" line="251" />
            <source>%1 — click to show it in the oscilloscope</source>
            <translation>%1 – klicken, um ihn im Oszilloskop anzuzeigen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/view.py" line="254" />
            <source>%1 — offline: measuring points show live values only with a valve online.</source>
            <translation>%1 – offline: Messpunkte zeigen Live-Werte nur mit einem Ventil online.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/view.py" line="308" />
            <source>Zoom to fit</source>
            <translation>An Fenster anpassen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/view.py" line="309" />
            <source>Zoom in</source>
            <translation>Vergrößern</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/view.py" line="310" />
            <source>Zoom out</source>
            <translation>Verkleinern</translation>
        </message>
    </context>
    <context>
        <name>Emcy</name>
        <message>
            <location filename="../prm9tool/views/emcy.py" line="13" />
            <source>Warning: electronics temperature above 70 °C</source>
            <translation>Warnung: Elektroniktemperatur über 70 °C</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/emcy.py" line="14" />
            <source>General error</source>
            <translation>Allgemeiner Fehler</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/emcy.py" line="15" />
            <source>Supply voltage out of range</source>
            <translation>Versorgungsspannung außerhalb des Bereichs</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/emcy.py" line="16" />
            <source>Setpoint signal error (e.g. 4…20 mA wire break)</source>
            <translation>Fehler Sollwertsignal (z. B. Kabelbruch 4…20 mA)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/emcy.py" line="17" />
            <source>Electronics temperature above 100 °C</source>
            <translation>Elektroniktemperatur über 100 °C</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/emcy.py" line="18" />
            <source>External sensor error</source>
            <translation>Fehler externer Sensor</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/emcy.py" line="19" />
            <source>Solenoid A over-current or disconnected</source>
            <translation>Magnet A Überstrom oder nicht angeschlossen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/emcy.py" line="20" />
            <source>Solenoid B over-current or disconnected</source>
            <translation>Magnet B Überstrom oder nicht angeschlossen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/emcy.py" line="21" />
            <source>Internal position sensor error</source>
            <translation>Fehler interner Wegsensor</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/emcy.py" line="23" />
            <source>Unknown error</source>
            <translation>Unbekannter Fehler</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/emcy.py" line="35" />
            <source>ok</source>
            <translation>ok</translation>
        </message>
    </context>
    <context>
        <name>EmulatorDialog</name>
        <message>
            <location filename="../prm9tool/views/hid_dialog.py" line="64" />
            <source>Add emulated valve</source>
            <translation>Emuliertes Ventil hinzufügen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/hid_dialog.py" line="72" />
            <source>Serial number:</source>
            <translation>Seriennummer:</translation>
        </message>
    </context>
    <context>
        <name>FileWorkflow</name>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="79" />
            <source>untitled</source>
            <translation>unbenannt</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="83" />
            <source>Unsaved changes</source>
            <translation>Ungespeicherte Änderungen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="84" />
            <source>The parameters in “{0}” have been changed. Save the changes?</source>
            <translation>Die Parameter in „{0}“ wurden geändert. Änderungen speichern?</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="98" />
            <source>New parameter set for {0}</source>
            <translation>Neuer Parametersatz für {0}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="107" />
            <source>Open parameter file</source>
            <translation>Parameterdatei öffnen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="109" />
            <source>Parameter files (*.prm);;All files (*)</source>
            <translation>Parameterdateien (*.prm);;Alle Dateien (*)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="120" />
            <source>File not found</source>
            <translation>Datei nicht gefunden</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="121" />
            <source>“{0}” no longer exists; it was removed from the list.</source>
            <translation>„{0}“ existiert nicht mehr; die Datei wurde aus der Liste entfernt.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="135" />
            <source>Cannot open “{0}”</source>
            <translation>„{0}“ kann nicht geöffnet werden</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="139" />
            <source>Opened {0}</source>
            <translation>{0} geöffnet</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="144" />
            <source>Opened with warnings</source>
            <translation>Mit Warnungen geöffnet</translation>
        </message>
        <message numerus="yes">
            <location filename="../prm9tool/views/file_workflow.py" line="146" />
            <source>“{0}” was opened; %n warning(s) were found.</source>
            <translation>
                <numerusform>„{0}“ wurde geöffnet; %n Warnung gefunden.</numerusform>
                <numerusform>„{0}“ wurde geöffnet; %n Warnungen gefunden.</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="163" />
            <source>Save parameter file</source>
            <translation>Parameterdatei speichern</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="165" />
            <source>Parameter files (*.prm)</source>
            <translation>Parameterdateien (*.prm)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="181" />
            <source>Cannot save “{0}”</source>
            <translation>„{0}“ kann nicht gespeichert werden</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="184" />
            <source>Saved {0}</source>
            <translation>{0} gespeichert</translation>
        </message>
        <message numerus="yes">
            <location filename="../prm9tool/views/file_workflow.py" line="202" />
            <source>%n more problem(s) in the details.</source>
            <translation>
                <numerusform>%n weiteres Problem in den Details.</numerusform>
                <numerusform>%n weitere Probleme in den Details.</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>GeneratorPanel</name>
        <message>
            <location filename="../prm9tool/views/scope_generator.py" line="140" />
            <source>Setpoint generator</source>
            <translation>Sollwertgenerator</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_generator.py" line="142" />
            <source>Step</source>
            <translation>Sprung</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_generator.py" line="143" />
            <source>Square</source>
            <translation>Rechteck</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_generator.py" line="144" />
            <source>Sine</source>
            <translation>Sinus</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_generator.py" line="148" />
            <source>Waveform</source>
            <translation>Signalform</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_generator.py" line="148" />
            <source>Period</source>
            <translation>Periode</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_generator.py" line="148" />
            <source>Amplitude</source>
            <translation>Amplitude</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_generator.py" line="148" />
            <source>Offset</source>
            <translation>Offset</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_generator.py" line="153" />
            <source>Step and square: height of the step above the offset. Sine: peak value. In % of the setpoint range.</source>
            <translation>Sprung und Rechteck: Höhe des Sprungs über dem Offset. Sinus: Scheitelwert. In % des Sollwertbereichs.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_generator.py" line="171" />
            <source>Stop generator</source>
            <translation>Generator stoppen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_generator.py" line="171" />
            <source>Start generator</source>
            <translation>Generator starten</translation>
        </message>
    </context>
    <context>
        <name>HelpWindow</name>
        <message>
            <location filename="../prm9tool/views/help_dialog.py" line="43" />
            <source>prm9tool help</source>
            <translation>prm9tool – Hilfe</translation>
        </message>
    </context>
    <context>
        <name>HidConfigurationDialog</name>
        <message>
            <location filename="../prm9tool/views/hid_dialog.py" line="135" />
            <source>HID configuration</source>
            <translation>HID-Konfiguration</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/hid_dialog.py" line="138" />
            <source>Valves connected to this computer and emulated valves. Choose the one to communicate with.</source>
            <translation>An diesen Computer angeschlossene und emulierte Ventile. Wählen Sie das Ventil für die Kommunikation.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/hid_dialog.py" line="144" />
            <source>Connection</source>
            <translation>Verbindung</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/hid_dialog.py" line="145" />
            <source>Type key</source>
            <translation>Typschlüssel</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/hid_dialog.py" line="146" />
            <source>Serial number</source>
            <translation>Seriennummer</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/hid_dialog.py" line="147" />
            <source>Firmware</source>
            <translation>Firmware</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/hid_dialog.py" line="148" />
            <source>Description</source>
            <translation>Beschreibung</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/hid_dialog.py" line="151" />
            <source>Add emulated valve…</source>
            <translation>Emuliertes Ventil hinzufügen…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/hid_dialog.py" line="152" />
            <source>Remove emulated valve</source>
            <translation>Emuliertes Ventil entfernen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/hid_dialog.py" line="153" />
            <source>Refresh</source>
            <translation>Aktualisieren</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/hid_dialog.py" line="167" />
            <source>Listing the valves failed: {0}</source>
            <translation>Auflisten der Ventile fehlgeschlagen: {0}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/hid_dialog.py" line="182" />
            <source>Emulated valve</source>
            <translation>Emuliertes Ventil</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/hid_dialog.py" line="182" />
            <source>USB</source>
            <translation>USB</translation>
        </message>
    </context>
    <context>
        <name>LinearizationDialog</name>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/linearization.py" line="162" />
            <source>Input X (%)</source>
            <translation>Eingang X (%)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/linearization.py" line="162" />
            <source>Output Y (%)</source>
            <translation>Ausgang Y (%)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/linearization.py" line="163" />
            <source>Reset to a straight line</source>
            <translation>Auf eine Gerade zurücksetzen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/linearization.py" line="165" />
            <source>Input (%)</source>
            <translation>Eingang (%)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/linearization.py" line="165" />
            <source>Output (%)</source>
            <translation>Ausgang (%)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/linearization.py" line="209" />
            <source>Linearization point %1</source>
            <translation>Linearisierungspunkt %1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/linearization.py" line="228" />
            <source>Linearization reset to a straight line</source>
            <translation>Linearisierung auf eine Gerade zurückgesetzt</translation>
        </message>
    </context>
    <context>
        <name>MainActions</name>
        <message>
            <location filename="../prm9tool/views/actions.py" line="78" />
            <source>&amp;New…</source>
            <translation>&amp;Neu…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="79" />
            <source>New parameter set from a valve type key</source>
            <translation>Neuer Parametersatz aus einem Ventil-Typschlüssel</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="82" />
            <source>&amp;Open…</source>
            <translation>Ö&amp;ffnen…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="83" />
            <source>Open a parameter file (*.prm)</source>
            <translation>Parameterdatei (*.prm) öffnen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="86" />
            <source>&amp;Save</source>
            <translation>&amp;Speichern</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="87" />
            <source>Save the parameter file (*.prm)</source>
            <translation>Parameterdatei (*.prm) speichern</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="90" />
            <source>Save &amp;As…</source>
            <translation>Speichern &amp;unter…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="91" />
            <source>Save the parameters under another name</source>
            <translation>Parameter unter einem anderen Namen speichern</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="94" />
            <source>&amp;Undo</source>
            <translation>&amp;Rückgängig</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="94" />
            <source>Undo the last change</source>
            <translation>Letzte Änderung rückgängig machen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="97" />
            <source>&amp;Redo</source>
            <translation>&amp;Wiederherstellen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="98" />
            <source>Redo the change undone last</source>
            <translation>Zuletzt rückgängig gemachte Änderung wiederherstellen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="101" />
            <source>&amp;Print…</source>
            <translation>&amp;Drucken…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="102" />
            <source>Print the current parameter record</source>
            <translation>Aktuellen Parametersatz drucken</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="105" />
            <source>&amp;Export PDF…</source>
            <translation>PDF &amp;exportieren…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="106" />
            <source>Save the parameter record as PDF</source>
            <translation>Parameterprotokoll als PDF speichern</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="109" />
            <source>E&amp;xit</source>
            <translation>&amp;Beenden</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="109" />
            <source>Quit prm9tool</source>
            <translation>prm9tool beenden</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="112" />
            <source>&amp;Flow diagram</source>
            <translation>&amp;Ablaufdiagramm</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="113" />
            <source>Show the signal-flow diagram</source>
            <translation>Signalflussdiagramm anzeigen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="116" />
            <source>&amp;Parameter list</source>
            <translation>&amp;Parameterliste</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="117" />
            <source>Show all parameters as a table</source>
            <translation>Alle Parameter als Tabelle anzeigen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="120" />
            <source>&amp;Oscilloscope</source>
            <translation>&amp;Oszilloskop</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="121" />
            <source>Show values in real time (online mode only)</source>
            <translation>Werte in Echtzeit anzeigen (nur im Online-Modus)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="124" />
            <source>&amp;CANopen window…</source>
            <translation>&amp;CANopen-Fenster…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="125" />
            <source>CANopen settings of the valve</source>
            <translation>CANopen-Einstellungen des Ventils</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="128" />
            <source>&amp;Basic</source>
            <translation>&amp;Basis</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="128" />
            <source>Basic parameter settings</source>
            <translation>Grundlegende Parametereinstellungen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="131" />
            <source>&amp;Expert…</source>
            <translation>&amp;Experte…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="132" />
            <source>All settings including controllers and linearization</source>
            <translation>Alle Einstellungen einschließlich Regler und Linearisierung</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="134" />
            <source>&amp;Change Expert password…</source>
            <translation>Experten&amp;passwort ändern…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="136" />
            <source>Valve &amp;selection…</source>
            <translation>Ventil&amp;auswahl…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="137" />
            <source>Choose the valve configuration by its type key</source>
            <translation>Ventilkonfiguration über den Typschlüssel wählen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="140" />
            <source>Valve s&amp;tatus…</source>
            <translation>Ventil&amp;status…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="141" />
            <source>State, firmware, serial number and errors of the valve</source>
            <translation>Zustand, Firmware, Seriennummer und Fehler des Ventils</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="144" />
            <source>&amp;Upload to valve</source>
            <translation>In das Ventil &amp;hochladen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="145" />
            <source>Write the parameters into the valve</source>
            <translation>Parameter in das Ventil schreiben</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="148" />
            <source>&amp;Download from valve</source>
            <translation>Aus dem Ventil &amp;herunterladen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="149" />
            <source>Read the parameters of the valve into the program</source>
            <translation>Parameter des Ventils in das Programm lesen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="152" />
            <source>Restore &amp;factory values…</source>
            <translation>&amp;Werkseinstellungen wiederherstellen…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="153" />
            <source>Return the parameters to the factory values</source>
            <translation>Parameter auf die Werkseinstellungen zurücksetzen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="156" />
            <source>&amp;Restart valve…</source>
            <translation>Ventil &amp;neu starten…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="157" />
            <source>Restart the valve electronics (only with the hydraulics disconnected)</source>
            <translation>Ventilelektronik neu starten (nur bei getrennter Hydraulik)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="163" />
            <source>&amp;HID configuration…</source>
            <translation>&amp;HID-Konfiguration…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="164" />
            <source>Choose the valve to communicate with</source>
            <translation>Ventil für die Kommunikation wählen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="167" />
            <source>O&amp;nline mode</source>
            <translation>O&amp;nline-Modus</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="168" />
            <source>Connect to the valve</source>
            <translation>Mit dem Ventil verbinden</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="171" />
            <source>O&amp;ffline mode</source>
            <translation>O&amp;ffline-Modus</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="172" />
            <source>Disconnect from the valve</source>
            <translation>Verbindung zum Ventil trennen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="175" />
            <location filename="../prm9tool/views/actions.py" line="287" />
            <source>&amp;Help</source>
            <translation>&amp;Hilfe</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="175" />
            <source>How to use prm9tool</source>
            <translation>Bedienung von prm9tool</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="178" />
            <source>Home&amp;page</source>
            <translation>Home&amp;page</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="179" />
            <source>Open the manufacturer's homepage</source>
            <translation>Homepage des Herstellers öffnen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="182" />
            <source>&amp;About prm9tool</source>
            <translation>Ü&amp;ber prm9tool</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="183" />
            <source>Versions and contact</source>
            <translation>Versionen und Kontakt</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="283" />
            <source>&amp;File</source>
            <translation>&amp;Datei</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="284" />
            <source>&amp;View</source>
            <translation>&amp;Ansicht</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="285" />
            <source>&amp;Valve</source>
            <translation>&amp;Ventil</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="286" />
            <source>&amp;Communication</source>
            <translation>&amp;Kommunikation</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="288" />
            <source>Open &amp;recent</source>
            <translation>&amp;Zuletzt geöffnet</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="289" />
            <source>&amp;Access level</source>
            <translation>&amp;Berechtigungsstufe</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="290" />
            <source>&amp;Language</source>
            <translation>&amp;Sprache</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="296" />
            <source>Toolbar</source>
            <translation>Werkzeugleiste</translation>
        </message>
    </context>
    <context>
        <name>MainStatusBar</name>
        <message>
            <location filename="../prm9tool/views/status_bar.py" line="72" />
            <source>ONLINE</source>
            <translation>ONLINE</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/status_bar.py" line="72" />
            <source>OFFLINE</source>
            <translation>OFFLINE</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/status_bar.py" line="73" />
            <source>Mode: {0}</source>
            <translation>Modus: {0}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/status_bar.py" line="74" />
            <source>Status: {0}</source>
            <translation>Status: {0}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/status_bar.py" line="75" />
            <source>FW: {0}</source>
            <translation>FW: {0}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/status_bar.py" line="76" />
            <source>untitled</source>
            <translation>unbenannt</translation>
        </message>
    </context>
    <context>
        <name>MainWindow</name>
        <message>
            <location filename="../prm9tool/views/main_window.py" line="119" />
            <source>The oscilloscope works in online mode only.</source>
            <translation>Das Oszilloskop arbeitet nur im Online-Modus.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/main_window.py" line="232" />
            <source>untitled</source>
            <translation>unbenannt</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/main_window.py" line="295" />
            <source>prm9tool</source>
            <translation>prm9tool</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/main_window.py" line="296" />
            <source>Parameterization of PRM9 proportional directional valves.</source>
            <translation>Parametrierung von PRM9-Proportional-Wegeventilen.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/main_window.py" line="297" />
            <source>Free software under the GNU General Public License v3 or later.</source>
            <translation>Freie Software unter der GNU General Public License v3 oder später.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/main_window.py" line="300" />
            <source>About prm9tool</source>
            <translation>Über prm9tool</translation>
        </message>
    </context>
    <context>
        <name>OnlineDiffDialog</name>
        <message>
            <location filename="../prm9tool/views/online_dialogs.py" line="57" />
            <source>Document and valve differ</source>
            <translation>Dokument und Ventil unterscheiden sich</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/online_dialogs.py" line="68" />
            <source>Take the valve's values</source>
            <translation>Werte des Ventils übernehmen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/online_dialogs.py" line="69" />
            <source>Send the document's values</source>
            <translation>Werte des Dokuments senden</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/online_dialogs.py" line="73" />
            <source>The document is for another valve variant; it cannot be sent.</source>
            <translation>Das Dokument gehört zu einer anderen Ventilvariante; es kann nicht gesendet werden.</translation>
        </message>
        <message numerus="yes">
            <location filename="../prm9tool/views/online_dialogs.py" line="88" />
            <source>%n value(s) in the document differ from the valve.</source>
            <translation>
                <numerusform>%n Wert im Dokument weicht vom Ventil ab.</numerusform>
                <numerusform>%n Werte im Dokument weichen vom Ventil ab.</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../prm9tool/views/online_dialogs.py" line="91" />
            <source>Document type key: {0} — valve type key: {1}</source>
            <translation>Typschlüssel des Dokuments: {0} – Typschlüssel des Ventils: {1}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/online_dialogs.py" line="96" />
            <source>The valve is of another variant: only its values can be taken.</source>
            <translation>Das Ventil ist eine andere Variante: nur seine Werte können übernommen werden.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/online_dialogs.py" line="98" />
            <source>Cancel stays offline; the document is not changed and nothing is written.</source>
            <translation>Abbrechen bleibt offline; das Dokument bleibt unverändert und nichts wird geschrieben.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/online_dialogs.py" line="107" />
            <source>Mnemonic</source>
            <translation>Kürzel</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/online_dialogs.py" line="107" />
            <source>Description</source>
            <translation>Beschreibung</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/online_dialogs.py" line="107" />
            <source>Document</source>
            <translation>Dokument</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/online_dialogs.py" line="107" />
            <source>Valve</source>
            <translation>Ventil</translation>
        </message>
    </context>
    <context>
        <name>ParameterEditDialog</name>
        <message>
            <location filename="../prm9tool/views/parameter_dialog.py" line="93" />
            <source>Parameter {0}</source>
            <translation>Parameter {0}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_dialog.py" line="98" />
            <source>Current value:</source>
            <translation>Aktueller Wert:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_dialog.py" line="99" />
            <source>Allowed range:</source>
            <translation>Zulässiger Bereich:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_dialog.py" line="100" />
            <source>Factory default:</source>
            <translation>Werkseinstellung:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_dialog.py" line="101" />
            <source>New value:</source>
            <translation>Neuer Wert:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_dialog.py" line="111" />
            <source>At Basic access level all ramps are set together: {0}.</source>
            <translation>In der Basisstufe werden alle Rampen gemeinsam eingestellt: {0}.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_dialog.py" line="119" />
            <source>Read-only value of the valve.</source>
            <translation>Nur lesbarer Wert des Ventils.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_dialog.py" line="120" />
            <source>Can only be changed at Expert access level.</source>
            <translation>Nur in der Expertenstufe änderbar.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_dialog.py" line="150" />
            <source>{0}: “{1}” is not a number.</source>
            <translation>{0}: „{1}“ ist keine Zahl.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_dialog.py" line="155" />
            <source>{0}: {1}{2} is outside the allowed range {3}{2}.</source>
            <translation>{0}: {1}{2} liegt außerhalb des zulässigen Bereichs {3}{2}.</translation>
        </message>
    </context>
    <context>
        <name>ParameterListView</name>
        <message>
            <location filename="../prm9tool/views/parameter_view.py" line="80" />
            <source>Search mnemonic or description…</source>
            <translation>Kürzel oder Beschreibung suchen…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_view.py" line="81" />
            <source>Modified only</source>
            <translation>Nur geänderte</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_view.py" line="83" />
            <source>Show only the values that differ from the factory defaults</source>
            <translation>Nur Werte anzeigen, die von der Werkseinstellung abweichen</translation>
        </message>
    </context>
    <context>
        <name>ParameterTableModel</name>
        <message>
            <location filename="../prm9tool/views/parameter_model.py" line="121" />
            <source>Mnemonic</source>
            <translation>Kürzel</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_model.py" line="122" />
            <source>Description</source>
            <translation>Beschreibung</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_model.py" line="123" />
            <source>Value</source>
            <translation>Wert</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_model.py" line="124" />
            <source>Unit</source>
            <translation>Einheit</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_model.py" line="173" />
            <source>Range: {0} … {1} {2}</source>
            <translation>Bereich: {0} … {1} {2}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_model.py" line="174" />
            <source>Factory default: {0} {1}</source>
            <translation>Werkseinstellung: {0} {1}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_model.py" line="182" />
            <source>Read-only value of the valve.</source>
            <translation>Nur lesbarer Wert des Ventils.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_model.py" line="184" />
            <source>Can only be changed at Expert access level.</source>
            <translation>Nur in der Expertenstufe änderbar.</translation>
        </message>
    </context>
    <context>
        <name>PasswordDialog</name>
        <message>
            <location filename="../prm9tool/views/access_dialog.py" line="38" />
            <source>Expert access level</source>
            <translation>Expertenstufe</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/access_dialog.py" line="43" />
            <source>The Expert level unlocks the controllers and the linearizations. Changing them needs the appropriate qualification.</source>
            <translation>Die Expertenstufe gibt die Regler und die Linearisierungen frei. Ihre Änderung erfordert die entsprechende Qualifikation.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/access_dialog.py" line="54" />
            <source>Password:</source>
            <translation>Passwort:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/access_dialog.py" line="65" />
            <source>Wrong password.</source>
            <translation>Falsches Passwort.</translation>
        </message>
    </context>
    <context>
        <name>RampsDialog</name>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/ramps.py" line="49" />
            <source>All ramps (for a 100 % step)</source>
            <translation>Alle Rampen (für einen 100-%-Sprung)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/ramps.py" line="62" />
            <source>the ramps differ</source>
            <translation>die Rampen unterscheiden sich</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/ramps.py" line="66" />
            <source>Basic access level: one time sets all ramps. Expert level sets each ramp on its own.</source>
            <translation>Basisstufe: eine Zeit stellt alle Rampen ein. Die Expertenstufe stellt jede Rampe einzeln ein.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/ramps.py" line="69" />
            <source>Each time is for a 100 % step; a 50 % step takes half as long.</source>
            <translation>Jede Zeit gilt für einen 100-%-Sprung; ein 50-%-Sprung dauert halb so lange.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/ramps.py" line="93" />
            <source>100 % step</source>
            <translation>100-%-Sprung</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/ramps.py" line="94" />
            <source>50 % step</source>
            <translation>50-%-Sprung</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/ramps.py" line="107" />
            <source>Time (ms)</source>
            <translation>Zeit (ms)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/ramps.py" line="108" />
            <source>Demand value (%)</source>
            <translation>Sollwert (%)</translation>
        </message>
    </context>
    <context>
        <name>Record</name>
        <message>
            <location filename="../prm9tool/views/record.py" line="76" />
            <source>untitled</source>
            <translation>unbenannt</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record.py" line="80" />
            <source>Type key</source>
            <translation>Typschlüssel</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record.py" line="81" />
            <source>Serial number</source>
            <translation>Seriennummer</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record.py" line="82" />
            <source>Firmware</source>
            <translation>Firmware</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record.py" line="83" />
            <source>File</source>
            <translation>Datei</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record.py" line="84" />
            <source>Date</source>
            <translation>Datum</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record.py" line="85" />
            <source>Access level</source>
            <translation>Berechtigungsstufe</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record.py" line="95" />
            <source>Mnemonic</source>
            <translation>Kürzel</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record.py" line="96" />
            <source>Description</source>
            <translation>Beschreibung</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record.py" line="97" />
            <source>Value</source>
            <translation>Wert</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record.py" line="98" />
            <source>Unit</source>
            <translation>Einheit</translation>
        </message>
    </context>
    <context>
        <name>RecordActions</name>
        <message>
            <location filename="../prm9tool/views/record_actions.py" line="38" />
            <source>Expert</source>
            <translation>Experte</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record_actions.py" line="38" />
            <source>Basic</source>
            <translation>Basis</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record_actions.py" line="59" />
            <source>Parameter record printed</source>
            <translation>Parameterprotokoll gedruckt</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record_actions.py" line="69" />
            <location filename="../prm9tool/views/record_actions.py" line="88" />
            <source>Export PDF</source>
            <translation>PDF exportieren</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record_actions.py" line="69" />
            <source>PDF files (*.pdf)</source>
            <translation>PDF-Dateien (*.pdf)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record_actions.py" line="89" />
            <source>Cannot write “{0}”: {1}</source>
            <translation>„{0}“ kann nicht geschrieben werden: {1}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record_actions.py" line="93" />
            <source>Parameter record saved as {0}</source>
            <translation>Parameterprotokoll gespeichert als {0}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record_actions.py" line="97" />
            <source>PRM9 parameter record {0}</source>
            <translation>PRM9-Parameterprotokoll {0}</translation>
        </message>
    </context>
    <context>
        <name>RestartDialog</name>
        <message>
            <location filename="../prm9tool/views/online_dialogs.py" line="130" />
            <source>Restart valve</source>
            <translation>Ventil neu starten</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/online_dialogs.py" line="133" />
            <source>&lt;b&gt;Restarting the valve electronics is only allowed with the hydraulic circuit disconnected.&lt;/b&gt;&lt;br&gt;During the restart the spool returns to its spring-centred position and the setpoint is ignored for a few seconds.</source>
            <translation>&lt;b&gt;Ein Neustart der Ventilelektronik ist nur bei getrenntem Hydraulikkreis erlaubt.&lt;/b&gt;&lt;br&gt;Während des Neustarts kehrt der Schieber in die federzentrierte Mittelstellung zurück und der Sollwert wird einige Sekunden ignoriert.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/online_dialogs.py" line="139" />
            <source>The hydraulics are disconnected</source>
            <translation>Die Hydraulik ist getrennt</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/online_dialogs.py" line="142" />
            <source>Restart</source>
            <translation>Neu starten</translation>
        </message>
    </context>
    <context>
        <name>ScopeDisplay</name>
        <message>
            <location filename="../prm9tool/views/scope_display.py" line="183" />
            <source>the samples between cursors A and B</source>
            <translation>die Abtastwerte zwischen Cursor A und B</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_display.py" line="186" />
            <source>the visible window</source>
            <translation>das sichtbare Fenster</translation>
        </message>
    </context>
    <context>
        <name>ScopePlot</name>
        <message>
            <location filename="../prm9tool/views/scope_plot.py" line="159" />
            <source>Auto</source>
            <translation>Auto</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_plot.py" line="160" />
            <source>Scale this channel to its data again</source>
            <translation>Diesen Kanal wieder an seine Daten anpassen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_plot.py" line="192" />
            <source>Time from trigger [ms]</source>
            <translation>Zeit ab Trigger [ms]</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_plot.py" line="192" />
            <source>Time from trigger [s]</source>
            <translation>Zeit ab Trigger [s]</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_plot.py" line="194" />
            <source>Time [ms]</source>
            <translation>Zeit [ms]</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_plot.py" line="194" />
            <source>Time [s]</source>
            <translation>Zeit [s]</translation>
        </message>
    </context>
    <context>
        <name>ScopeWidget</name>
        <message>
            <location filename="../prm9tool/views/scope.py" line="128" />
            <source>Select at least one measuring point on the right.</source>
            <translation>Wählen Sie rechts mindestens einen Messpunkt.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="173" />
            <source>The recording could not start: {0}</source>
            <translation>Die Aufzeichnung konnte nicht starten: {0}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="257" />
            <source>Stopped. Choose up to three measuring points and press Start.</source>
            <translation>Gestoppt. Wählen Sie bis zu drei Messpunkte und drücken Sie Start.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="259" />
            <source>Single capture complete. Resume arms the trigger again.</source>
            <translation>Einzelaufnahme abgeschlossen. Fortsetzen schärft den Trigger erneut.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="261" />
            <source>Paused: zoom and pan with the mouse; recording continues.</source>
            <translation>Pausiert: mit der Maus zoomen und verschieben; die Aufzeichnung läuft weiter.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="263" />
            <source>Waiting for the trigger…</source>
            <translation>Warten auf den Trigger…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="270" />
            <source>Recording at {0} Hz.</source>
            <translation>Aufzeichnung mit {0} Hz.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="272" />
            <source>{0} samples lost on the link.</source>
            <translation>{0} Abtastwerte auf der Verbindung verloren.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="277" />
            <source>The oscilloscope needs a connected valve: go online (Communication → Online).</source>
            <translation>Das Oszilloskop braucht ein verbundenes Ventil: wechseln Sie online (Kommunikation → Online).</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="285" />
            <source>Setpoint generator</source>
            <translation>Sollwertgenerator</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="296" />
            <source>The generator will drive the valve's setpoint and the valve will move.
Make sure the machine is safe to move. Start the generator?</source>
            <translation>Der Generator steuert den Sollwert des Ventils und das Ventil wird sich bewegen.
Stellen Sie sicher, dass die Maschine sich gefahrlos bewegen kann. Generator starten?</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="310" />
            <source>The link dropped: the setpoint generator has stopped.</source>
            <translation>Die Verbindung ist abgebrochen: der Sollwertgenerator wurde gestoppt.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="318" />
            <source>Nothing recorded yet.</source>
            <translation>Noch nichts aufgezeichnet.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="326" />
            <source>Could not write {0}.</source>
            <translation>{0} konnte nicht geschrieben werden.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="330" />
            <source>Export CSV</source>
            <translation>CSV exportieren</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="330" />
            <source>CSV files (*.csv)</source>
            <translation>CSV-Dateien (*.csv)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="337" />
            <source>Export PNG</source>
            <translation>PNG exportieren</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="337" />
            <source>PNG images (*.png)</source>
            <translation>PNG-Bilder (*.png)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="346" />
            <source>Export</source>
            <translation>Export</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="348" />
            <source>Saved {0}.</source>
            <translation>{0} gespeichert.</translation>
        </message>
    </context>
    <context>
        <name>SensorScalingDialog</name>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/sensor_scaling.py" line="33" />
            <source>Sensor signal in (%)</source>
            <translation>Sensorsignal ein (%)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/sensor_scaling.py" line="34" />
            <source>Process actual value (%)</source>
            <translation>Prozessistwert (%)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/sensor_scaling.py" line="40" />
            <source>1:1</source>
            <translation>1:1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/sensor_scaling.py" line="42" />
            <source>after offset and gain</source>
            <translation>nach Offset und Verstärkung</translation>
        </message>
    </context>
    <context>
        <name>SignalInputDialog</name>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/signal_input.py" line="59" />
            <source>%1 — recommended</source>
            <translation>%1 – empfohlen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/signal_input.py" line="67" />
            <source>Recommended for this coil layout (manual table 8-4) are the types marked 'recommended'. With positive polarity a positive setpoint drives coil A.</source>
            <translation>Für diese Spulenanordnung empfohlen (Anleitung Tabelle 8-4) sind die mit „empfohlen“ gekennzeichneten Typen. Bei positiver Polarität steuert ein positiver Sollwert Spule A an.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/signal_input.py" line="74" />
            <source>With inverted polarity the sensor signal enters the process loop with a negative sign.</source>
            <translation>Bei invertierter Polarität geht das Sensorsignal mit negativem Vorzeichen in den Prozessregelkreis ein.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/signal_input.py" line="89" />
            <source>Input signal (%1)</source>
            <translation>Eingangssignal (%1)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/signal_input.py" line="90" />
            <source>Internal value (%)</source>
            <translation>Interner Wert (%)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/signal_input.py" line="93" />
            <source>internal value</source>
            <translation>interner Wert</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/signal_input.py" line="96" />
            <source>This type is not recommended for a valve with %1 (manual table 8-4).</source>
            <translation>Dieser Typ wird für ein Ventil mit %1 nicht empfohlen (Anleitung Tabelle 8-4).</translation>
        </message>
    </context>
    <context>
        <name>StepPanel</name>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="135" />
            <source>Step response</source>
            <translation>Sprungantwort</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="136" />
            <source>Only between cursors A and B</source>
            <translation>Nur zwischen Cursor A und B</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="138" />
            <source>Reference</source>
            <translation>Referenz</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="139" />
            <source>Response</source>
            <translation>Antwort</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="140" />
            <source>Step</source>
            <translation>Sprung</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="141" />
            <source>Rise time 10–90 %</source>
            <translation>Anstiegszeit 10–90 %</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="142" />
            <source>Overshoot</source>
            <translation>Überschwingen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="143" />
            <source>Settling time ±2 %</source>
            <translation>Einschwingzeit ±2 %</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="144" />
            <source>Steady-state error</source>
            <translation>Bleibende Regelabweichung</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="149" />
            <location filename="../prm9tool/views/scope_readout.py" line="157" />
            <source>(none: step on the response)</source>
            <translation>(keine: Sprung auf der Antwort)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="186" />
            <source>No step found in {0}.</source>
            <translation>Kein Sprung in {0} gefunden.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="198" />
            <source>not settled in the window</source>
            <translation>im Fenster nicht eingeschwungen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="201" />
            <source>Measured on {0}.</source>
            <translation>Gemessen auf {0}.</translation>
        </message>
    </context>
    <context>
        <name>StepResponse</name>
        <message>
            <location filename="../prm9tool/tuning.py" line="109" />
            <source>not reached</source>
            <translation>nicht erreicht</translation>
        </message>
        <message>
            <location filename="../prm9tool/tuning.py" line="115" />
            <source>Step %1 %: overshoot %2 %, rise time %3, settling (±2 %) %4, remaining error %5 %</source>
            <translation>Sprung %1 %: Überschwingen %2 %, Anstiegszeit %3, Einschwingen (±2 %) %4, bleibende Abweichung %5 %</translation>
        </message>
    </context>
    <context>
        <name>ThresholdGainDialog</name>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/threshold_gain.py" line="65" />
            <source>Control deviation in (%)</source>
            <translation>Regelabweichung ein (%)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/threshold_gain.py" line="65" />
            <source>Setpoint in (%)</source>
            <translation>Sollwert ein (%)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/threshold_gain.py" line="66" />
            <source>Control deviation out (%)</source>
            <translation>Regelabweichung aus (%)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/threshold_gain.py" line="66" />
            <source>Setpoint out (%)</source>
            <translation>Sollwert aus (%)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/threshold_gain.py" line="73" />
            <source>1:1</source>
            <translation>1:1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/threshold_gain.py" line="75" />
            <source>output</source>
            <translation>Ausgang</translation>
        </message>
    </context>
    <context>
        <name>ValveConnection</name>
        <message>
            <location filename="../prm9tool/connection.py" line="117" />
            <source>The valve connection is busy; wait until it is done.</source>
            <translation>Die Verbindung zum Ventil ist beschäftigt; warten Sie, bis sie fertig ist.</translation>
        </message>
        <message>
            <location filename="../prm9tool/connection.py" line="118" />
            <source>Already online; go offline first.</source>
            <translation>Bereits online; zuerst offline gehen.</translation>
        </message>
        <message>
            <location filename="../prm9tool/connection.py" line="221" />
            <location filename="../prm9tool/connection.py" line="227" />
            <source>Not connected to a valve.</source>
            <translation>Nicht mit einem Ventil verbunden.</translation>
        </message>
    </context>
    <context>
        <name>ValveSelectionDialog</name>
        <message>
            <location filename="../prm9tool/views/valve_selection.py" line="92" />
            <source>Valve selection</source>
            <translation>Ventilauswahl</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_selection.py" line="95" />
            <source>Choose the valve by its type key. The new parameter set holds the factory defaults of that type; valve-specific calibration data is not included.</source>
            <translation>Wählen Sie das Ventil über seinen Typschlüssel. Der neue Parametersatz enthält die Werkseinstellungen dieses Typs; ventilspezifische Kalibrierdaten sind nicht enthalten.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_selection.py" line="100" />
            <source>Nominal size:</source>
            <translation>Nenngröße:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_selection.py" line="101" />
            <source>Spool:</source>
            <translation>Schieber:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_selection.py" line="102" />
            <source>Nominal flow (Δp 10 bar):</source>
            <translation>Nennvolumenstrom (Δp 10 bar):</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_selection.py" line="103" />
            <source>Supply voltage:</source>
            <translation>Versorgungsspannung:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_selection.py" line="104" />
            <source>Configuration:</source>
            <translation>Konfiguration:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_selection.py" line="105" />
            <source>Interface:</source>
            <translation>Schnittstelle:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_selection.py" line="106" />
            <source>Type key:</source>
            <translation>Typschlüssel:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_selection.py" line="110" />
            <source>E02 – internal position feedback</source>
            <translation>E02 – interne Lagerückführung</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_selection.py" line="111" />
            <source>E04 – internal position and external feedback</source>
            <translation>E04 – interne Lage- und externe Rückführung</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_selection.py" line="113" />
            <source> (assumption)</source>
            <translation> (Annahme)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_selection.py" line="119" />
            <source>two solenoids A and B</source>
            <translation>zwei Magnete A und B</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_selection.py" line="120" />
            <source>one solenoid on side {0}</source>
            <translation>ein Magnet auf Seite {0}</translation>
        </message>
    </context>
    <context>
        <name>ValveStatusWindow</name>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="144" />
            <source>Valve status</source>
            <translation>Ventilstatus</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="145" />
            <source>Valve</source>
            <translation>Ventil</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="146" />
            <source>Active errors</source>
            <translation>Aktive Fehler</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="147" />
            <source>LEDs</source>
            <translation>LEDs</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="149" />
            <source>Mode:</source>
            <translation>Modus:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="150" />
            <source>Firmware version:</source>
            <translation>Firmware-Version:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="151" />
            <source>Serial number:</source>
            <translation>Seriennummer:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="152" />
            <source>Type key:</source>
            <translation>Typschlüssel:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="153" />
            <source>Device state:</source>
            <translation>Gerätezustand:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="154" />
            <source>CANopen NMT state:</source>
            <translation>CANopen-NMT-Zustand:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="155" />
            <source>Temperature:</source>
            <translation>Temperatur:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="156" />
            <source>Supply voltage:</source>
            <translation>Versorgungsspannung:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="160" />
            <source>LED 1 power</source>
            <translation>LED 1 Versorgung</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="160" />
            <source>LED 2 error</source>
            <translation>LED 2 Fehler</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="160" />
            <source>LED 3 CAN</source>
            <translation>LED 3 CAN</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="187" />
            <source>ONLINE</source>
            <translation>ONLINE</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="187" />
            <source>OFFLINE</source>
            <translation>OFFLINE</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="197" />
            <source>No status: the valve is offline.</source>
            <translation>Kein Status: das Ventil ist offline.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="216" />
            <source>white</source>
            <translation>weiß</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="217" />
            <source>green</source>
            <translation>grün</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="218" />
            <source>orange</source>
            <translation>orange</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="219" />
            <source>red</source>
            <translation>rot</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="220" />
            <source>blue</source>
            <translation>blau</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="221" />
            <source>magenta</source>
            <translation>magenta</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="224" />
            <source>on</source>
            <translation>leuchtet</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="225" />
            <source>blinking 1 Hz</source>
            <translation>blinkt 1 Hz</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="226" />
            <source>blinking 2 Hz</source>
            <translation>blinkt 2 Hz</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="227" />
            <source>blinking 2.5 Hz</source>
            <translation>blinkt 2,5 Hz</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="228" />
            <source>single flash</source>
            <translation>Einfachblitz</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="229" />
            <source>double flash</source>
            <translation>Doppelblitz</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="230" />
            <source>triple flash</source>
            <translation>Dreifachblitz</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="231" />
            <source>quadruple flash</source>
            <translation>Vierfachblitz</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="232" />
            <source>power-up</source>
            <translation>Einschalten</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="235" />
            <source>off</source>
            <translation>aus</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="247" />
            <source>No error.</source>
            <translation>Kein Fehler.</translation>
        </message>
    </context>
    <context>
        <name>ValveWorkflow</name>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="97" />
            <source>Connecting to {0}…</source>
            <translation>Verbinden mit {0}…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="106" />
            <source>Store changes in the valve</source>
            <translation>Änderungen im Ventil speichern</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="108" />
            <source>Values changed online are active in the valve but not stored: a restart of the valve would undo them. Store them in the valve now?</source>
            <translation>Online geänderte Werte sind im Ventil aktiv, aber nicht gespeichert: ein Neustart des Ventils würde sie rückgängig machen. Jetzt im Ventil speichern?</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="126" />
            <source>Offline</source>
            <translation>Offline</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="128" />
            <location filename="../prm9tool/views/valve_workflow.py" line="136" />
            <source>Reading the valve's parameters…</source>
            <translation>Parameter des Ventils werden gelesen…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="152" />
            <source>Online: document and valve agree</source>
            <translation>Online: Dokument und Ventil stimmen überein</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="163" />
            <source>Values read from the valve</source>
            <translation>Aus dem Ventil gelesene Werte</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="179" />
            <source>Online: parameters read from the valve</source>
            <translation>Online: Parameter aus dem Ventil gelesen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="206" />
            <source>The valve reports an unknown type key: {0}</source>
            <translation>Das Ventil meldet einen unbekannten Typschlüssel: {0}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="221" />
            <source>Upload to valve</source>
            <translation>In das Ventil hochladen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="223" />
            <source>The document is for a {0} valve, the connected valve is a {1} valve. Choose the matching valve type or download the valve's parameters first.</source>
            <translation>Das Dokument ist für ein Ventil {0}, das angeschlossene Ventil ist ein Ventil {1}. Wählen Sie den passenden Ventiltyp oder laden Sie zuerst die Parameter des Ventils herunter.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="229" />
            <source>Uploading the parameters to the valve…</source>
            <translation>Parameter werden in das Ventil hochgeladen…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="234" />
            <source>Downloading the parameters from the valve…</source>
            <translation>Parameter werden aus dem Ventil heruntergeladen…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="242" />
            <source>Reset the valve's stored parameters to the factory values and restart it? Only allowed with the hydraulics disconnected.</source>
            <translation>Die gespeicherten Parameter des Ventils auf die Werkseinstellungen zurücksetzen und das Ventil neu starten? Nur bei getrennter Hydraulik erlaubt.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="246" />
            <source>Set every parameter of the document to the factory default?</source>
            <translation>Alle Parameter des Dokuments auf die Werkseinstellung setzen?</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="251" />
            <location filename="../prm9tool/views/valve_workflow.py" line="260" />
            <source>Restore factory values</source>
            <translation>Werkseinstellungen wiederherstellen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="262" />
            <source>Restoring the factory values…</source>
            <translation>Werkseinstellungen werden wiederhergestellt…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="270" />
            <source>Restarting the valve…</source>
            <translation>Ventil wird neu gestartet…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="279" />
            <source>Download from valve</source>
            <translation>Aus dem Ventil herunterladen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="281" />
            <source>Factory values of the valve</source>
            <translation>Werkseinstellungen des Ventils</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="283" />
            <source>The valve restarted</source>
            <translation>Das Ventil wurde neu gestartet</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="290" />
            <source>The valve stored its parameters</source>
            <translation>Das Ventil hat seine Parameter gespeichert</translation>
        </message>
        <message numerus="yes">
            <location filename="../prm9tool/views/valve_workflow.py" line="297" />
            <source>%n parameter(s) written, verified and stored</source>
            <translation>
                <numerusform>%n Parameter geschrieben, geprüft und gespeichert</numerusform>
                <numerusform>%n Parameter geschrieben, geprüft und gespeichert</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="305" />
            <source>Upload failed</source>
            <translation>Hochladen fehlgeschlagen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="307" />
            <source>The upload failed at step “{0}”. Nothing was stored: after a restart the valve holds its previous parameters.</source>
            <translation>Das Hochladen ist im Schritt „{0}“ fehlgeschlagen. Nichts wurde gespeichert: nach einem Neustart hat das Ventil seine vorherigen Parameter.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="324" />
            <source>Valve communication</source>
            <translation>Kommunikation mit dem Ventil</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="331" />
            <source>Connection to the valve lost</source>
            <translation>Verbindung zum Ventil verloren</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="333" />
            <source>The connection to the valve was lost; prm9tool is offline now.
Every value is kept in the document: save it, or go online again and send it.</source>
            <translation>Die Verbindung zum Ventil ist verloren; prm9tool ist jetzt offline.
Alle Werte bleiben im Dokument erhalten: speichern Sie es oder gehen Sie wieder online und senden Sie es.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="341" />
            <source>Backup of the valve's parameters saved: {0}</source>
            <translation>Sicherung der Ventilparameter gespeichert: {0}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="348" />
            <source>Cancel</source>
            <translation>Abbrechen</translation>
        </message>
    </context>
</TS>
