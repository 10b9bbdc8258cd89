<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="cs_CZ">
    <context>
        <name>BlockDialog</name>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/base.py" line="211" />
            <source>Read only: %1 (View → Access level)</source>
            <translation>Jen pro čtení: %1 (Náhled → Úroveň oprávnění)</translation>
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
            <translation>Ventil čte své dva otočné přepínače pouze při zapnutí; označené řádky jsou polohy načtené při posledním spuštění. Zde nastavený terminátor, Node ID a přenosová rychlost se uloží do ventilu a platí po dalším restartu.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="162" />
            <source>Interface / bit-rate switch</source>
            <translation>Přepínač rozhraní / přenosové rychlosti</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="163" />
            <source>Node-ID switch</source>
            <translation>Přepínač Node ID</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="164" />
            <source>Settings made by software (USB)</source>
            <translation>Nastavení softwarem (USB)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="166" />
            <location filename="../prm9tool/views/canopen_window.py" line="168" />
            <source>Position</source>
            <translation>Poloha</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="166" />
            <source>Interface / bit rate</source>
            <translation>Rozhraní / přenosová rychlost</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="166" />
            <source>Terminator</source>
            <translation>Terminátor</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="168" />
            <source>Node ID</source>
            <translation>Node ID</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="169" />
            <source>CAN terminator 120 Ω</source>
            <translation>Terminátor CAN 120 Ω</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="170" />
            <source>Node ID (node switch at 0)</source>
            <translation>Node ID (přepínač Node ID v poloze 0)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="171" />
            <source>Bit rate (node switch at 0)</source>
            <translation>Přenosová rychlost (přepínač Node ID v poloze 0)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="172" />
            <location filename="../prm9tool/views/canopen_window.py" line="187" />
            <location filename="../prm9tool/views/canopen_window.py" line="292" />
            <source>on</source>
            <translation>zapnutý</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="182" />
            <source>CANopen off, analog setpoint only</source>
            <translation>CANopen vypnuto, pouze analogová žádaná hodnota</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="184" />
            <source>reserved (as position 0)</source>
            <translation>rezervováno (jako poloha 0)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="189" />
            <source>off (on by software)</source>
            <translation>vypnutý (zapnutí softwarem)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="190" />
            <source>CANopen, %1</source>
            <translation>CANopen, %1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="195" />
            <source>set by software: 1 … 127 (below)</source>
            <translation>nastavení softwarem: 1 … 127 (níže)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="197" />
            <source>LSS, automatic bit rate</source>
            <translation>LSS, automatická přenosová rychlost</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="225" />
            <source>Position read by the valve at its last power-up</source>
            <translation>Poloha načtená ventilem při posledním zapnutí</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="240" />
            <source>The node-ID switch is not at 0: the switch sets the node ID.</source>
            <translation>Přepínač Node ID není v poloze 0: Node ID určuje přepínač.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="260" />
            <source>This valve type has no CANopen interface (no -CA in the type key).</source>
            <translation>Tento typ ventilu nemá rozhraní CANopen (typový klíč bez -CA).</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="263" />
            <source>Offline: the switch positions are unknown. Settings changed here go into the document; upload it to the valve and restart the valve.</source>
            <translation>Offline: polohy přepínačů nejsou známé. Zde změněná nastavení se uloží do dokumentu; načtěte jej do ventilu a ventil restartujte.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="267" />
            <source>Reading the switch positions from the valve …</source>
            <translation>Čtení poloh přepínačů z ventilu …</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="269" />
            <source>Switch positions read from the valve at its last power-up.</source>
            <translation>Polohy přepínačů načtené ventilem při posledním zapnutí.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="272" />
            <source>With the node-ID switch at 0 or 1 the terminator follows the software setting below, whatever the interface switch says.</source>
            <translation>Je-li přepínač Node ID v poloze 0 nebo 1, řídí se terminátor nastavením softwaru níže bez ohledu na přepínač rozhraní.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="286" />
            <source>After the next restart the valve uses:</source>
            <translation>Po dalším restartu ventil použije:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="288" />
            <source>The valve uses:</source>
            <translation>Ventil používá:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="290" />
            <source>CANopen off (analog setpoint only).</source>
            <translation>CANopen vypnuto (pouze analogová žádaná hodnota).</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="292" />
            <source>off</source>
            <translation>vypnutý</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="294" />
            <source>node ID %1, %2, terminator %3.</source>
            <translation>Node ID %1, %2, terminátor %3.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="322" />
            <source>Changed in the document. Upload it to the valve; the change takes effect after the valve restarts.</source>
            <translation>Změněno v dokumentu. Načtěte jej do ventilu; změna se projeví po restartu ventilu.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/canopen_window.py" line="337" />
            <source>Written to the valve and stored. The change takes effect after the valve restarts (Valve → Restart valve).</source>
            <translation>Zapsáno do ventilu a uloženo. Změna se projeví po restartu ventilu (Ventil → Restart ventilu).</translation>
        </message>
    </context>
    <context>
        <name>ChangePasswordDialog</name>
        <message>
            <location filename="../prm9tool/views/access_dialog.py" line="76" />
            <source>Change Expert password</source>
            <translation>Změna hesla pro expertní úroveň</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/access_dialog.py" line="87" />
            <source>Current password:</source>
            <translation>Současné heslo:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/access_dialog.py" line="88" />
            <source>New password:</source>
            <translation>Nové heslo:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/access_dialog.py" line="89" />
            <source>Repeat new password:</source>
            <translation>Nové heslo znovu:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/access_dialog.py" line="97" />
            <source>The current password is wrong.</source>
            <translation>Současné heslo je chybné.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/access_dialog.py" line="99" />
            <source>The new password must have at least {0} characters.</source>
            <translation>Nové heslo musí mít alespoň {0} znaky.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/access_dialog.py" line="101" />
            <source>The two new passwords differ.</source>
            <translation>Obě nová hesla se liší.</translation>
        </message>
    </context>
    <context>
        <name>ChannelPanel</name>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="54" />
            <source>Measuring points</source>
            <translation>Měřicí body</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="91" />
            <source>At most three measuring points: {0} replaces {1}.</source>
            <translation>Nejvýše tři měřicí body: {0} nahrazuje {1}.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="109" />
            <source>At most three measuring points can be recorded at once. Switch one off before adding {0}.</source>
            <translation>Současně lze zaznamenávat nejvýše tři měřicí body. Před přidáním {0} jeden vypněte.</translation>
        </message>
    </context>
    <context>
        <name>ControlPanel</name>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="229" />
            <source>Recording</source>
            <translation>Záznam</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="230" />
            <source>Interval</source>
            <translation>Interval</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="231" />
            <source>Time window</source>
            <translation>Časové okno</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="232" />
            <source>Start</source>
            <translation>Start</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="233" />
            <source>Stop</source>
            <translation>Stop</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="235" />
            <source>Trigger</source>
            <translation>Spouštění</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="237" />
            <source>Roll (no trigger)</source>
            <translation>Průběžně (bez spouštění)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="238" />
            <source>Auto</source>
            <translation>Auto</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="239" />
            <source>Normal</source>
            <translation>Normální</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="240" />
            <source>Single</source>
            <translation>Jednorázově</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="241" />
            <source>Rising edge</source>
            <translation>Náběžná hrana</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="242" />
            <source>Falling edge</source>
            <translation>Sestupná hrana</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="247" />
            <source>Pre-trigger</source>
            <translation>Předstih</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="248" />
            <source>Trigger level in the trigger channel's unit</source>
            <translation>Úroveň spouštění v jednotce spouštěcího kanálu</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="249" />
            <source>Display and export</source>
            <translation>Zobrazení a export</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="250" />
            <source>Cursors A/B</source>
            <translation>Kurzory A/B</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="251" />
            <source>Same scale per unit</source>
            <translation>Stejné měřítko pro jednotku</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="253" />
            <source>Autoscaled channels with the same unit share one scale</source>
            <translation>Automaticky škálované kanály se stejnou jednotkou sdílejí jedno měřítko</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="255" />
            <source>Export CSV</source>
            <translation>Export CSV</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="258" />
            <source>Visible window…</source>
            <translation>Viditelné okno…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="259" />
            <source>Whole recording…</source>
            <translation>Celý záznam…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="260" />
            <source>Export PNG…</source>
            <translation>Export PNG…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="267" />
            <source>Resume</source>
            <translation>Pokračovat</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_panels.py" line="267" />
            <source>Pause</source>
            <translation>Pozastavit</translation>
        </message>
    </context>
    <context>
        <name>ControllerDialog</name>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/controller.py" line="118" />
            <source>No simulation available.</source>
            <translation>Simulace není k dispozici.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/controller.py" line="132" />
            <source>Simulation failed: %1</source>
            <translation>Simulace selhala: %1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/controller.py" line="138" />
            <source>setpoint</source>
            <translation>žádaná hodnota</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/controller.py" line="142" />
            <source>applied values</source>
            <translation>použité hodnoty</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/controller.py" line="143" />
            <source>actual value</source>
            <translation>skutečná hodnota</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/controller.py" line="149" />
            <source>Time (ms)</source>
            <translation>Čas (ms)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/controller.py" line="149" />
            <source>Value (%)</source>
            <translation>Hodnota (%)</translation>
        </message>
    </context>
    <context>
        <name>CurrentDitherDialog</name>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/current_dither.py" line="47" />
            <source>Nominal coil current CURNORM: %1 mA — no limit may exceed it.</source>
            <translation>Jmenovitý proud cívky CURNORM: %1 mA – žádná mez jej nesmí překročit.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/current_dither.py" line="59" />
            <source>coil %1</source>
            <translation>cívka %1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/current_dither.py" line="60" />
            <source>limit %1</source>
            <translation>mez %1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/current_dither.py" line="64" />
            <source>Coil current (mA)</source>
            <translation>Proud cívky (mA)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/current_dither.py" line="66" />
            <source>Coil current (mA), coil B downwards</source>
            <translation>Proud cívky (mA), cívka B směrem dolů</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/current_dither.py" line="67" />
            <source>Time (ms)</source>
            <translation>Čas (ms)</translation>
        </message>
    </context>
    <context>
        <name>CursorPanel</name>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="68" />
            <source>Cursors</source>
            <translation>Kurzory</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="94" />
            <source>Switch the cursors on to measure.</source>
            <translation>Pro měření zapněte kurzory.</translation>
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
            <translation>charakteristika</translation>
        </message>
    </context>
    <context>
        <name>DiagramBlock</name>
        <message>
            <location filename="../prm9tool/views/diagram/scene.py" line="107" />
            <source>spool position (LVDT)</source>
            <translation>poloha šoupátka (LVDT)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="110" />
            <source>Setpoint input</source>
            <translation>Vstup žádané hodnoty</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="115" />
            <source>Threshold</source>
            <translation>Práh</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="120" />
            <source>Gain &amp; offset</source>
            <translation>Zesílení a posunutí</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="127" />
            <source>Linearization</source>
            <translation>Linearizace</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="132" />
            <source>Ramps</source>
            <translation>Rampy</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="138" />
            <source>Deviation gain &amp; offset</source>
            <translation>Odchylka: zesílení a posunutí</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="145" />
            <source>Process PIDT1</source>
            <translation>Procesní regulátor PIDT1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="152" />
            <source>External sensor</source>
            <translation>Externí snímač</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="159" />
            <source>Sensor offset &amp; gain</source>
            <translation>Snímač: posunutí a zesílení</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="166" />
            <source>Sensor linearization</source>
            <translation>Linearizace snímače</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="175" />
            <source>Position PIDT1</source>
            <translation>Regulátor polohy PIDT1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="182" />
            <source>Current limiter</source>
            <translation>Omezovač proudu</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/layout.py" line="187" />
            <source>Dither</source>
            <translation>Dynamické mazání</translation>
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
            <translation>Napájení</translation>
        </message>
    </context>
    <context>
        <name>DiagramSummary</name>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="40" />
            <location filename="../prm9tool/views/diagram/summary.py" line="126" />
            <source>Polarity: %1</source>
            <translation>Polarita: %1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="45" />
            <source>Threshold %1</source>
            <translation>Práh %1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="56" />
            <location filename="../prm9tool/views/diagram/summary.py" line="133" />
            <source>Gain %1</source>
            <translation>Zesílení %1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="59" />
            <location filename="../prm9tool/views/diagram/summary.py" line="132" />
            <source>Offset %1</source>
            <translation>Posunutí %1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="69" />
            <source>9-point curve on</source>
            <translation>9bodová křivka zapnuta</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="71" />
            <source>off (1:1)</source>
            <translation>vypnuto (1:1)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="96" />
            <source>Coil %1: %2</source>
            <translation>Cívka %1: %2</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="106" />
            <source>Amplitude %1</source>
            <translation>Amplituda %1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="107" />
            <source>Frequency %1</source>
            <translation>Frekvence %1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="115" />
            <source>coils A and B</source>
            <translation>cívky A a B</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="116" />
            <source>coil A only</source>
            <translation>pouze cívka A</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="117" />
            <source>coil B only</source>
            <translation>pouze cívka B</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="139" />
            <source>Voltage, temperature</source>
            <translation>Napětí, teplota</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="140" />
            <source>(live values)</source>
            <translation>(aktuální hodnoty)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="146" />
            <source>Node ID %1 (switch 0)</source>
            <translation>Node ID %1 (přepínač 0)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/summary.py" line="149" />
            <source>Terminator %1</source>
            <translation>Terminátor %1</translation>
        </message>
    </context>
    <context>
        <name>DiagramView</name>
        <message>
            <location filename="../prm9tool/views/diagram/view.py" line="223" />
            <source>Values measured by the valve; see the red measuring points.</source>
            <translation>Hodnoty měřené ventilem; viz červené měřicí body.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/view.py" line="227" />
            <source>Click to edit: %1</source>
            <translation>Klepnutím upravíte: %1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/view.py" line="239" />
            <source>(View → Access level)</source>
            <translation>(Náhled → Úroveň oprávnění)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/view.py" line="243" />
            <source>Online, the valve type is that of the connected valve.</source>
            <translation>V režimu online je typ ventilu dán připojeným ventilem.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/view.py" line="251" />
            <source>%1 — click to show it in the oscilloscope</source>
            <translation>%1 – klepnutím jej zobrazíte v osciloskopu</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/view.py" line="254" />
            <source>%1 — offline: measuring points show live values only with a valve online.</source>
            <translation>%1 – offline: měřicí body zobrazují aktuální hodnoty jen s ventilem v režimu online.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/view.py" line="308" />
            <source>Zoom to fit</source>
            <translation>Přizpůsobit oknu</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/view.py" line="309" />
            <source>Zoom in</source>
            <translation>Přiblížit</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/view.py" line="310" />
            <source>Zoom out</source>
            <translation>Oddálit</translation>
        </message>
    </context>
    <context>
        <name>Emcy</name>
        <message>
            <location filename="../prm9tool/views/emcy.py" line="13" />
            <source>Warning: electronics temperature above 70 °C</source>
            <translation>Varování: teplota elektroniky nad 70 °C</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/emcy.py" line="14" />
            <source>General error</source>
            <translation>Obecná chyba</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/emcy.py" line="15" />
            <source>Supply voltage out of range</source>
            <translation>Napájecí napětí mimo rozsah</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/emcy.py" line="16" />
            <source>Setpoint signal error (e.g. 4…20 mA wire break)</source>
            <translation>Chyba signálu žádané hodnoty (např. přerušení vodiče 4…20 mA)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/emcy.py" line="17" />
            <source>Electronics temperature above 100 °C</source>
            <translation>Teplota elektroniky nad 100 °C</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/emcy.py" line="18" />
            <source>External sensor error</source>
            <translation>Chyba externího snímače</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/emcy.py" line="19" />
            <source>Solenoid A over-current or disconnected</source>
            <translation>Cívka A: nadproud nebo odpojení</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/emcy.py" line="20" />
            <source>Solenoid B over-current or disconnected</source>
            <translation>Cívka B: nadproud nebo odpojení</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/emcy.py" line="21" />
            <source>Internal position sensor error</source>
            <translation>Chyba interního snímače polohy</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/emcy.py" line="23" />
            <source>Unknown error</source>
            <translation>Neznámá chyba</translation>
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
            <translation>Přidat emulovaný ventil</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/hid_dialog.py" line="72" />
            <source>Serial number:</source>
            <translation>Výrobní číslo:</translation>
        </message>
    </context>
    <context>
        <name>FileWorkflow</name>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="79" />
            <source>untitled</source>
            <translation>nepojmenovaná</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="83" />
            <source>Unsaved changes</source>
            <translation>Neuložené změny</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="84" />
            <source>The parameters in “{0}” have been changed. Save the changes?</source>
            <translation>Parametry v „{0}“ byly změněny. Uložit změny?</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="98" />
            <source>New parameter set for {0}</source>
            <translation>Nový záznam parametrů pro {0}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="107" />
            <source>Open parameter file</source>
            <translation>Otevřít záznam parametrů</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="109" />
            <source>Parameter files (*.prm);;All files (*)</source>
            <translation>Záznamy parametrů (*.prm);;Všechny soubory (*)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="120" />
            <source>File not found</source>
            <translation>Soubor nenalezen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="121" />
            <source>“{0}” no longer exists; it was removed from the list.</source>
            <translation>„{0}“ již neexistuje; byl odstraněn ze seznamu.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="135" />
            <source>Cannot open “{0}”</source>
            <translation>„{0}“ nelze otevřít</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="139" />
            <source>Opened {0}</source>
            <translation>Otevřeno: {0}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="144" />
            <source>Opened with warnings</source>
            <translation>Otevřeno s varováními</translation>
        </message>
        <message numerus="yes">
            <location filename="../prm9tool/views/file_workflow.py" line="146" />
            <source>“{0}” was opened; %n warning(s) were found.</source>
            <translation>
                <numerusform>„{0}“ byl otevřen; nalezeno %n varování.</numerusform>
                <numerusform>„{0}“ byl otevřen; nalezena %n varování.</numerusform>
                <numerusform>„{0}“ byl otevřen; nalezeno %n varování.</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="163" />
            <source>Save parameter file</source>
            <translation>Uložit záznam parametrů</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="165" />
            <source>Parameter files (*.prm)</source>
            <translation>Záznamy parametrů (*.prm)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="181" />
            <source>Cannot save “{0}”</source>
            <translation>„{0}“ nelze uložit</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/file_workflow.py" line="184" />
            <source>Saved {0}</source>
            <translation>Uloženo: {0}</translation>
        </message>
        <message numerus="yes">
            <location filename="../prm9tool/views/file_workflow.py" line="202" />
            <source>%n more problem(s) in the details.</source>
            <translation>
                <numerusform>Další %n problém v podrobnostech.</numerusform>
                <numerusform>Další %n problémy v podrobnostech.</numerusform>
                <numerusform>Dalších %n problémů v podrobnostech.</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>GeneratorPanel</name>
        <message>
            <location filename="../prm9tool/views/scope_generator.py" line="140" />
            <source>Setpoint generator</source>
            <translation>Generátor žádané hodnoty</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_generator.py" line="142" />
            <source>Step</source>
            <translation>Skok</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_generator.py" line="143" />
            <source>Square</source>
            <translation>Obdélník</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_generator.py" line="144" />
            <source>Sine</source>
            <translation>Sinus</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_generator.py" line="148" />
            <source>Waveform</source>
            <translation>Průběh</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_generator.py" line="148" />
            <source>Period</source>
            <translation>Perioda</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_generator.py" line="148" />
            <source>Amplitude</source>
            <translation>Amplituda</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_generator.py" line="148" />
            <source>Offset</source>
            <translation>Posunutí</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_generator.py" line="153" />
            <source>Step and square: height of the step above the offset. Sine: peak value. In % of the setpoint range.</source>
            <translation>Skok a obdélník: výška skoku nad posunutím. Sinus: amplituda. V % rozsahu žádané hodnoty.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_generator.py" line="171" />
            <source>Stop generator</source>
            <translation>Zastavit generátor</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_generator.py" line="171" />
            <source>Start generator</source>
            <translation>Spustit generátor</translation>
        </message>
    </context>
    <context>
        <name>HelpWindow</name>
        <message>
            <location filename="../prm9tool/views/help_dialog.py" line="43" />
            <source>prm9tool help</source>
            <translation>prm9tool – nápověda</translation>
        </message>
    </context>
    <context>
        <name>HidConfigurationDialog</name>
        <message>
            <location filename="../prm9tool/views/hid_dialog.py" line="135" />
            <source>HID configuration</source>
            <translation>HID konfigurace</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/hid_dialog.py" line="138" />
            <source>Valves connected to this computer and emulated valves. Choose the one to communicate with.</source>
            <translation>Ventily připojené k tomuto počítači a emulované ventily. Zvolte ventil pro komunikaci.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/hid_dialog.py" line="144" />
            <source>Connection</source>
            <translation>Připojení</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/hid_dialog.py" line="145" />
            <source>Type key</source>
            <translation>Typový klíč</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/hid_dialog.py" line="146" />
            <source>Serial number</source>
            <translation>Výrobní číslo</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/hid_dialog.py" line="147" />
            <source>Firmware</source>
            <translation>Firmware</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/hid_dialog.py" line="148" />
            <source>Description</source>
            <translation>Popis</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/hid_dialog.py" line="151" />
            <source>Add emulated valve…</source>
            <translation>Přidat emulovaný ventil…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/hid_dialog.py" line="152" />
            <source>Remove emulated valve</source>
            <translation>Odebrat emulovaný ventil</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/hid_dialog.py" line="153" />
            <source>Refresh</source>
            <translation>Obnovit</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/hid_dialog.py" line="167" />
            <source>Listing the valves failed: {0}</source>
            <translation>Výpis ventilů selhal: {0}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/hid_dialog.py" line="182" />
            <source>Emulated valve</source>
            <translation>Emulovaný ventil</translation>
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
            <translation>Vstup X (%)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/linearization.py" line="162" />
            <source>Output Y (%)</source>
            <translation>Výstup Y (%)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/linearization.py" line="163" />
            <source>Reset to a straight line</source>
            <translation>Obnovit přímku</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/linearization.py" line="165" />
            <source>Input (%)</source>
            <translation>Vstup (%)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/linearization.py" line="165" />
            <source>Output (%)</source>
            <translation>Výstup (%)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/linearization.py" line="209" />
            <source>Linearization point %1</source>
            <translation>Bod linearizace %1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/linearization.py" line="228" />
            <source>Linearization reset to a straight line</source>
            <translation>Linearizace obnovena na přímku</translation>
        </message>
    </context>
    <context>
        <name>MainActions</name>
        <message>
            <location filename="../prm9tool/views/actions.py" line="78" />
            <source>&amp;New…</source>
            <translation>&amp;Nový…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="79" />
            <source>New parameter set from a valve type key</source>
            <translation>Nový záznam parametrů podle typového klíče ventilu</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="82" />
            <source>&amp;Open…</source>
            <translation>&amp;Otevřít…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="83" />
            <source>Open a parameter file (*.prm)</source>
            <translation>Načtení záznamu parametrů (*.prm)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="86" />
            <source>&amp;Save</source>
            <translation>&amp;Uložit</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="87" />
            <source>Save the parameter file (*.prm)</source>
            <translation>Uložení záznamu parametrů (*.prm)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="90" />
            <source>Save &amp;As…</source>
            <translation>Uložit &amp;jako…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="91" />
            <source>Save the parameters under another name</source>
            <translation>Uložení záznamu parametrů pod jiným jménem</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="94" />
            <source>&amp;Undo</source>
            <translation>&amp;Zpět</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="94" />
            <source>Undo the last change</source>
            <translation>Vrátit poslední změnu</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="97" />
            <source>&amp;Redo</source>
            <translation>Z&amp;novu</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="98" />
            <source>Redo the change undone last</source>
            <translation>Znovu provést naposledy vrácenou změnu</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="101" />
            <source>&amp;Print…</source>
            <translation>&amp;Tisk…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="102" />
            <source>Print the current parameter record</source>
            <translation>Vytisknout aktuální záznam parametrů</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="105" />
            <source>&amp;Export PDF…</source>
            <translation>&amp;Export do PDF…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="106" />
            <source>Save the parameter record as PDF</source>
            <translation>Uložit protokol parametrů jako PDF</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="109" />
            <source>E&amp;xit</source>
            <translation>&amp;Konec</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="109" />
            <source>Quit prm9tool</source>
            <translation>Ukončit prm9tool</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="112" />
            <source>&amp;Flow diagram</source>
            <translation>&amp;Postupový diagram</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="113" />
            <source>Show the signal-flow diagram</source>
            <translation>Zobrazení signálového diagramu</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="116" />
            <source>&amp;Parameter list</source>
            <translation>&amp;Seznam parametrů</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="117" />
            <source>Show all parameters as a table</source>
            <translation>Zobrazení všech parametrů v tabulce</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="120" />
            <source>&amp;Oscilloscope</source>
            <translation>&amp;Osciloskop</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="121" />
            <source>Show values in real time (online mode only)</source>
            <translation>Zobrazení hodnot v reálném čase (pouze v režimu online)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="124" />
            <source>&amp;CANopen window…</source>
            <translation>Okno &amp;CANopen…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="125" />
            <source>CANopen settings of the valve</source>
            <translation>Nastavení CANopen ventilu</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="128" />
            <source>&amp;Basic</source>
            <translation>&amp;Základní</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="128" />
            <source>Basic parameter settings</source>
            <translation>Základní možnosti nastavování parametrů ventilu</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="131" />
            <source>&amp;Expert…</source>
            <translation>&amp;Expertní…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="132" />
            <source>All settings including controllers and linearization</source>
            <translation>Další možnosti nastavování parametrů (včetně regulátorů a linearizace)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="134" />
            <source>&amp;Change Expert password…</source>
            <translation>&amp;Změnit heslo pro expertní úroveň…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="136" />
            <source>Valve &amp;selection…</source>
            <translation>&amp;Výběr ventilu…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="137" />
            <source>Choose the valve configuration by its type key</source>
            <translation>Výběr konfigurace ventilu pomocí typového klíče</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="140" />
            <source>Valve s&amp;tatus…</source>
            <translation>S&amp;tav ventilu…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="141" />
            <source>State, firmware, serial number and errors of the valve</source>
            <translation>Stav, verze firmware, výrobní číslo a chyby ventilu</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="144" />
            <source>&amp;Upload to valve</source>
            <translation>&amp;Načtení do ventilu</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="145" />
            <source>Write the parameters into the valve</source>
            <translation>Zápis dat z programu do elektroniky ventilu</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="148" />
            <source>&amp;Download from valve</source>
            <translation>&amp;Stažení z ventilu</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="149" />
            <source>Read the parameters of the valve into the program</source>
            <translation>Načtení parametrů z elektroniky ventilu do programu</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="152" />
            <source>Restore &amp;factory values…</source>
            <translation>Obnovit &amp;tovární nastavení…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="153" />
            <source>Return the parameters to the factory values</source>
            <translation>Vrácení parametrů na tovární hodnoty</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="156" />
            <source>&amp;Restart valve…</source>
            <translation>&amp;Restart ventilu…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="157" />
            <source>Restart the valve electronics (only with the hydraulics disconnected)</source>
            <translation>Restartování elektroniky ventilu (dovoleno pouze při odpojeném hydraulickém obvodu)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="163" />
            <source>&amp;HID configuration…</source>
            <translation>&amp;HID konfigurace…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="164" />
            <source>Choose the valve to communicate with</source>
            <translation>Výběr ventilu pro komunikaci</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="167" />
            <source>O&amp;nline mode</source>
            <translation>Režim o&amp;nline</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="168" />
            <source>Connect to the valve</source>
            <translation>Přechod do režimu online</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="171" />
            <source>O&amp;ffline mode</source>
            <translation>Režim o&amp;ffline</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="172" />
            <source>Disconnect from the valve</source>
            <translation>Odpojení od elektroniky ventilu</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="175" />
            <location filename="../prm9tool/views/actions.py" line="287" />
            <source>&amp;Help</source>
            <translation>&amp;Nápověda</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="175" />
            <source>How to use prm9tool</source>
            <translation>Jak používat prm9tool</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="178" />
            <source>Home&amp;page</source>
            <translation>&amp;Domovská stránka</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="179" />
            <source>Open the manufacturer's homepage</source>
            <translation>Otevřít domovskou stránku výrobce</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="182" />
            <source>&amp;About prm9tool</source>
            <translation>&amp;O programu prm9tool</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="183" />
            <source>Versions and contact</source>
            <translation>Verze a kontakt</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="283" />
            <source>&amp;File</source>
            <translation>&amp;Soubor</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="284" />
            <source>&amp;View</source>
            <translation>Ná&amp;hled</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="285" />
            <source>&amp;Valve</source>
            <translation>&amp;Ventil</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="286" />
            <source>&amp;Communication</source>
            <translation>&amp;Komunikace</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="288" />
            <source>Open &amp;recent</source>
            <translation>Naposledy &amp;otevřené</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="289" />
            <source>&amp;Access level</source>
            <translation>Úroveň &amp;oprávnění</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="290" />
            <source>&amp;Language</source>
            <translation>&amp;Jazyk</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/actions.py" line="296" />
            <source>Toolbar</source>
            <translation>Panel nástrojů</translation>
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
            <translation>Režim: {0}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/status_bar.py" line="74" />
            <source>Status: {0}</source>
            <translation>Status: {0}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/status_bar.py" line="75" />
            <source>FW: {0}</source>
            <translation>Verze FW: {0}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/status_bar.py" line="76" />
            <source>untitled</source>
            <translation>nepojmenovaná</translation>
        </message>
    </context>
    <context>
        <name>MainWindow</name>
        <message>
            <location filename="../prm9tool/views/main_window.py" line="119" />
            <source>The oscilloscope works in online mode only.</source>
            <translation>Osciloskop je dostupný pouze v režimu online.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/main_window.py" line="232" />
            <source>untitled</source>
            <translation>nepojmenovaná</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/main_window.py" line="295" />
            <source>prm9tool</source>
            <translation>prm9tool</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/main_window.py" line="296" />
            <source>Parameterization of PRM9 proportional directional valves.</source>
            <translation>Nastavení parametrů proporcionálních rozváděčů PRM9.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/main_window.py" line="297" />
            <source>Free software under the GNU General Public License v3 or later.</source>
            <translation>Svobodný software pod licencí GNU General Public License v3 nebo novější.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/main_window.py" line="300" />
            <source>About prm9tool</source>
            <translation>O programu prm9tool</translation>
        </message>
    </context>
    <context>
        <name>OnlineDiffDialog</name>
        <message>
            <location filename="../prm9tool/views/online_dialogs.py" line="57" />
            <source>Document and valve differ</source>
            <translation>Dokument a ventil se liší</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/online_dialogs.py" line="68" />
            <source>Take the valve's values</source>
            <translation>Převzít hodnoty ventilu</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/online_dialogs.py" line="69" />
            <source>Send the document's values</source>
            <translation>Odeslat hodnoty dokumentu</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/online_dialogs.py" line="73" />
            <source>The document is for another valve variant; it cannot be sent.</source>
            <translation>Dokument je pro jinou variantu ventilu; nelze jej odeslat.</translation>
        </message>
        <message numerus="yes">
            <location filename="../prm9tool/views/online_dialogs.py" line="88" />
            <source>%n value(s) in the document differ from the valve.</source>
            <translation>
                <numerusform>%n hodnota v dokumentu se liší od ventilu.</numerusform>
                <numerusform>%n hodnoty v dokumentu se liší od ventilu.</numerusform>
                <numerusform>%n hodnot v dokumentu se liší od ventilu.</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../prm9tool/views/online_dialogs.py" line="91" />
            <source>Document type key: {0} — valve type key: {1}</source>
            <translation>Typový klíč dokumentu: {0} – typový klíč ventilu: {1}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/online_dialogs.py" line="96" />
            <source>The valve is of another variant: only its values can be taken.</source>
            <translation>Ventil je jiné varianty: lze pouze převzít jeho hodnoty.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/online_dialogs.py" line="98" />
            <source>Cancel stays offline; the document is not changed and nothing is written.</source>
            <translation>Zrušit ponechá režim offline; dokument se nezmění a nic se nezapíše.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/online_dialogs.py" line="107" />
            <source>Mnemonic</source>
            <translation>Zkratka</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/online_dialogs.py" line="107" />
            <source>Description</source>
            <translation>Popis</translation>
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
            <translation>Parametr {0}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_dialog.py" line="98" />
            <source>Current value:</source>
            <translation>Aktuální hodnota:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_dialog.py" line="99" />
            <source>Allowed range:</source>
            <translation>Přípustný rozsah:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_dialog.py" line="100" />
            <source>Factory default:</source>
            <translation>Tovární nastavení:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_dialog.py" line="101" />
            <source>New value:</source>
            <translation>Nová hodnota:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_dialog.py" line="111" />
            <source>At Basic access level all ramps are set together: {0}.</source>
            <translation>Na základní úrovni oprávnění se všechny rampy nastavují společně: {0}.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_dialog.py" line="119" />
            <source>Read-only value of the valve.</source>
            <translation>Hodnota ventilu pouze pro čtení.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_dialog.py" line="120" />
            <source>Can only be changed at Expert access level.</source>
            <translation>Lze změnit pouze na expertní úrovni oprávnění.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_dialog.py" line="150" />
            <source>{0}: “{1}” is not a number.</source>
            <translation>{0}: „{1}“ není číslo.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_dialog.py" line="155" />
            <source>{0}: {1}{2} is outside the allowed range {3}{2}.</source>
            <translation>{0}: {1}{2} je mimo přípustný rozsah {3}{2}.</translation>
        </message>
    </context>
    <context>
        <name>ParameterListView</name>
        <message>
            <location filename="../prm9tool/views/parameter_view.py" line="80" />
            <source>Search mnemonic or description…</source>
            <translation>Hledat zkratku nebo popis…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_view.py" line="81" />
            <source>Modified only</source>
            <translation>Jen změněné</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_view.py" line="83" />
            <source>Show only the values that differ from the factory defaults</source>
            <translation>Zobrazit jen hodnoty odlišné od továrního nastavení</translation>
        </message>
    </context>
    <context>
        <name>ParameterTableModel</name>
        <message>
            <location filename="../prm9tool/views/parameter_model.py" line="121" />
            <source>Mnemonic</source>
            <translation>Zkratka</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_model.py" line="122" />
            <source>Description</source>
            <translation>Popis</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_model.py" line="123" />
            <source>Value</source>
            <translation>Hodnota</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_model.py" line="124" />
            <source>Unit</source>
            <translation>Jednotka</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_model.py" line="173" />
            <source>Range: {0} … {1} {2}</source>
            <translation>Rozsah: {0} … {1} {2}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_model.py" line="174" />
            <source>Factory default: {0} {1}</source>
            <translation>Tovární nastavení: {0} {1}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_model.py" line="182" />
            <source>Read-only value of the valve.</source>
            <translation>Hodnota ventilu pouze pro čtení.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/parameter_model.py" line="184" />
            <source>Can only be changed at Expert access level.</source>
            <translation>Lze změnit pouze na expertní úrovni oprávnění.</translation>
        </message>
    </context>
    <context>
        <name>PasswordDialog</name>
        <message>
            <location filename="../prm9tool/views/access_dialog.py" line="38" />
            <source>Expert access level</source>
            <translation>Expertní úroveň oprávnění</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/access_dialog.py" line="43" />
            <source>The Expert level unlocks the controllers and the linearizations. Changing them needs the appropriate qualification.</source>
            <translation>Expertní úroveň zpřístupní regulátory a linearizace. Jejich změna vyžaduje odpovídající kvalifikaci.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/access_dialog.py" line="54" />
            <source>Password:</source>
            <translation>Heslo:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/access_dialog.py" line="65" />
            <source>Wrong password.</source>
            <translation>Chybné heslo.</translation>
        </message>
    </context>
    <context>
        <name>RampsDialog</name>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/ramps.py" line="49" />
            <source>All ramps (for a 100 % step)</source>
            <translation>Všechny rampy (pro skok 100 %)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/ramps.py" line="62" />
            <source>the ramps differ</source>
            <translation>rampy se liší</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/ramps.py" line="66" />
            <source>Basic access level: one time sets all ramps. Expert level sets each ramp on its own.</source>
            <translation>Základní úroveň: jeden čas nastaví všechny rampy. Na expertní úrovni se každá rampa nastavuje samostatně.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/ramps.py" line="69" />
            <source>Each time is for a 100 % step; a 50 % step takes half as long.</source>
            <translation>Každý čas platí pro skok 100 %; skok 50 % trvá poloviční dobu.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/ramps.py" line="93" />
            <source>100 % step</source>
            <translation>skok 100 %</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/ramps.py" line="94" />
            <source>50 % step</source>
            <translation>skok 50 %</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/ramps.py" line="107" />
            <source>Time (ms)</source>
            <translation>Čas (ms)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/ramps.py" line="108" />
            <source>Demand value (%)</source>
            <translation>Hodnota požadavku (%)</translation>
        </message>
    </context>
    <context>
        <name>Record</name>
        <message>
            <location filename="../prm9tool/views/record.py" line="76" />
            <source>untitled</source>
            <translation>nepojmenovaná</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record.py" line="80" />
            <source>Type key</source>
            <translation>Typový klíč</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record.py" line="81" />
            <source>Serial number</source>
            <translation>Výrobní číslo</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record.py" line="82" />
            <source>Firmware</source>
            <translation>Firmware</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record.py" line="83" />
            <source>File</source>
            <translation>Soubor</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record.py" line="84" />
            <source>Date</source>
            <translation>Datum</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record.py" line="85" />
            <source>Access level</source>
            <translation>Úroveň oprávnění</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record.py" line="95" />
            <source>Mnemonic</source>
            <translation>Zkratka</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record.py" line="96" />
            <source>Description</source>
            <translation>Popis</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record.py" line="97" />
            <source>Value</source>
            <translation>Hodnota</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record.py" line="98" />
            <source>Unit</source>
            <translation>Jednotka</translation>
        </message>
    </context>
    <context>
        <name>RecordActions</name>
        <message>
            <location filename="../prm9tool/views/record_actions.py" line="38" />
            <source>Expert</source>
            <translation>Expertní</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record_actions.py" line="38" />
            <source>Basic</source>
            <translation>Základní</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record_actions.py" line="59" />
            <source>Parameter record printed</source>
            <translation>Protokol parametrů vytištěn</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record_actions.py" line="69" />
            <location filename="../prm9tool/views/record_actions.py" line="88" />
            <source>Export PDF</source>
            <translation>Export do PDF</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record_actions.py" line="69" />
            <source>PDF files (*.pdf)</source>
            <translation>Soubory PDF (*.pdf)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record_actions.py" line="89" />
            <source>Cannot write “{0}”: {1}</source>
            <translation>„{0}“ nelze zapsat: {1}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record_actions.py" line="93" />
            <source>Parameter record saved as {0}</source>
            <translation>Protokol parametrů uložen jako {0}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/record_actions.py" line="97" />
            <source>PRM9 parameter record {0}</source>
            <translation>Protokol parametrů PRM9 {0}</translation>
        </message>
    </context>
    <context>
        <name>RestartDialog</name>
        <message>
            <location filename="../prm9tool/views/online_dialogs.py" line="130" />
            <source>Restart valve</source>
            <translation>Restart ventilu</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/online_dialogs.py" line="133" />
            <source>&lt;b&gt;Restarting the valve electronics is only allowed with the hydraulic circuit disconnected.&lt;/b&gt;&lt;br&gt;During the restart the spool returns to its spring-centred position and the setpoint is ignored for a few seconds.</source>
            <translation>&lt;b&gt;Restart elektroniky ventilu je dovolen pouze při odpojeném hydraulickém obvodu.&lt;/b&gt;&lt;br&gt;Během restartu se šoupátko vrátí působením středicích pružin do střední polohy a žádaná hodnota je několik sekund ignorována.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/online_dialogs.py" line="139" />
            <source>The hydraulics are disconnected</source>
            <translation>Hydraulický obvod je odpojen</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/online_dialogs.py" line="142" />
            <source>Restart</source>
            <translation>Restartovat</translation>
        </message>
    </context>
    <context>
        <name>ScopeDisplay</name>
        <message>
            <location filename="../prm9tool/views/scope_display.py" line="183" />
            <source>the samples between cursors A and B</source>
            <translation>vzorky mezi kurzory A a B</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_display.py" line="186" />
            <source>the visible window</source>
            <translation>viditelné okno</translation>
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
            <translation>Znovu přizpůsobit měřítko kanálu jeho datům</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_plot.py" line="192" />
            <source>Time from trigger [ms]</source>
            <translation>Čas od spuštění [ms]</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_plot.py" line="192" />
            <source>Time from trigger [s]</source>
            <translation>Čas od spuštění [s]</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_plot.py" line="194" />
            <source>Time [ms]</source>
            <translation>Čas [ms]</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_plot.py" line="194" />
            <source>Time [s]</source>
            <translation>Čas [s]</translation>
        </message>
    </context>
    <context>
        <name>ScopeWidget</name>
        <message>
            <location filename="../prm9tool/views/scope.py" line="128" />
            <source>Select at least one measuring point on the right.</source>
            <translation>Vpravo zvolte alespoň jeden měřicí bod.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="173" />
            <source>The recording could not start: {0}</source>
            <translation>Záznam nelze spustit: {0}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="257" />
            <source>Stopped. Choose up to three measuring points and press Start.</source>
            <translation>Zastaveno. Zvolte až tři měřicí body a stiskněte Start.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="259" />
            <source>Single capture complete. Resume arms the trigger again.</source>
            <translation>Jednorázový záznam dokončen. Pokračovat znovu aktivuje spouštění.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="261" />
            <source>Paused: zoom and pan with the mouse; recording continues.</source>
            <translation>Pozastaveno: přibližujte a posouvejte myší; záznam pokračuje.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="263" />
            <source>Waiting for the trigger…</source>
            <translation>Čekání na spouštění…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="270" />
            <source>Recording at {0} Hz.</source>
            <translation>Záznam s frekvencí {0} Hz.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="272" />
            <source>{0} samples lost on the link.</source>
            <translation>{0} vzorků ztraceno na spojení.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="277" />
            <source>The oscilloscope needs a connected valve: go online (Communication → Online).</source>
            <translation>Osciloskop potřebuje připojený ventil: přejděte do režimu online (Komunikace → Režim online).</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="285" />
            <source>Setpoint generator</source>
            <translation>Generátor žádané hodnoty</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="296" />
            <source>The generator will drive the valve's setpoint and the valve will move.
Make sure the machine is safe to move. Start the generator?</source>
            <translation>Generátor bude řídit žádanou hodnotu ventilu a ventil se bude pohybovat.
Ujistěte se, že pohyb stroje je bezpečný. Spustit generátor?</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="310" />
            <source>The link dropped: the setpoint generator has stopped.</source>
            <translation>Spojení se přerušilo: generátor žádané hodnoty se zastavil.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="318" />
            <source>Nothing recorded yet.</source>
            <translation>Zatím nic nezaznamenáno.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="326" />
            <source>Could not write {0}.</source>
            <translation>{0} nelze zapsat.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="330" />
            <source>Export CSV</source>
            <translation>Export CSV</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="330" />
            <source>CSV files (*.csv)</source>
            <translation>Soubory CSV (*.csv)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="337" />
            <source>Export PNG</source>
            <translation>Export PNG</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="337" />
            <source>PNG images (*.png)</source>
            <translation>Obrázky PNG (*.png)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="346" />
            <source>Export</source>
            <translation>Export</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope.py" line="348" />
            <source>Saved {0}.</source>
            <translation>Uloženo: {0}.</translation>
        </message>
    </context>
    <context>
        <name>SensorScalingDialog</name>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/sensor_scaling.py" line="33" />
            <source>Sensor signal in (%)</source>
            <translation>Signál snímače na vstupu (%)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/sensor_scaling.py" line="34" />
            <source>Process actual value (%)</source>
            <translation>Skutečná procesní veličina (%)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/sensor_scaling.py" line="40" />
            <source>1:1</source>
            <translation>1:1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/sensor_scaling.py" line="42" />
            <source>after offset and gain</source>
            <translation>za posunutím a zesílením</translation>
        </message>
    </context>
    <context>
        <name>SignalInputDialog</name>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/signal_input.py" line="59" />
            <source>%1 — recommended</source>
            <translation>%1 – doporučeno</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/signal_input.py" line="67" />
            <source>Recommended for this coil layout (manual table 8-4) are the types marked 'recommended'. With positive polarity a positive setpoint drives coil A.</source>
            <translation>Pro toto uspořádání cívek (příručka, tabulka 8-4) jsou doporučeny typy označené „doporučeno“. Při kladné polaritě kladná žádaná hodnota napájí cívku A.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/signal_input.py" line="74" />
            <source>With inverted polarity the sensor signal enters the process loop with a negative sign.</source>
            <translation>Při obrácené polaritě vstupuje signál snímače do regulační smyčky se záporným znaménkem.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/signal_input.py" line="89" />
            <source>Input signal (%1)</source>
            <translation>Vstupní signál (%1)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/signal_input.py" line="90" />
            <source>Internal value (%)</source>
            <translation>Interní hodnota (%)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/signal_input.py" line="93" />
            <source>internal value</source>
            <translation>interní hodnota</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/signal_input.py" line="96" />
            <source>This type is not recommended for a valve with %1 (manual table 8-4).</source>
            <translation>Tento typ se pro ventil s %1 nedoporučuje (příručka, tabulka 8-4).</translation>
        </message>
    </context>
    <context>
        <name>StepPanel</name>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="135" />
            <source>Step response</source>
            <translation>Přechodová charakteristika</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="136" />
            <source>Only between cursors A and B</source>
            <translation>Jen mezi kurzory A a B</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="138" />
            <source>Reference</source>
            <translation>Reference</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="139" />
            <source>Response</source>
            <translation>Odezva</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="140" />
            <source>Step</source>
            <translation>Skok</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="141" />
            <source>Rise time 10–90 %</source>
            <translation>Doba náběhu 10–90 %</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="142" />
            <source>Overshoot</source>
            <translation>Překmit</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="143" />
            <source>Settling time ±2 %</source>
            <translation>Doba ustálení ±2 %</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="144" />
            <source>Steady-state error</source>
            <translation>Trvalá regulační odchylka</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="149" />
            <location filename="../prm9tool/views/scope_readout.py" line="157" />
            <source>(none: step on the response)</source>
            <translation>(žádná: skok na odezvě)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="186" />
            <source>No step found in {0}.</source>
            <translation>V {0} nebyl nalezen žádný skok.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="198" />
            <source>not settled in the window</source>
            <translation>v okně neustáleno</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/scope_readout.py" line="201" />
            <source>Measured on {0}.</source>
            <translation>Měřeno na {0}.</translation>
        </message>
    </context>
    <context>
        <name>StepResponse</name>
        <message>
            <location filename="../prm9tool/tuning.py" line="109" />
            <source>not reached</source>
            <translation>nedosaženo</translation>
        </message>
        <message>
            <location filename="../prm9tool/tuning.py" line="115" />
            <source>Step %1 %: overshoot %2 %, rise time %3, settling (±2 %) %4, remaining error %5 %</source>
            <translation>Skok %1 %: překmit %2 %, doba náběhu %3, ustálení (±2 %) %4, zbývající odchylka %5 %</translation>
        </message>
    </context>
    <context>
        <name>ThresholdGainDialog</name>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/threshold_gain.py" line="65" />
            <source>Control deviation in (%)</source>
            <translation>Regulační odchylka na vstupu (%)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/threshold_gain.py" line="65" />
            <source>Setpoint in (%)</source>
            <translation>Žádaná hodnota na vstupu (%)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/threshold_gain.py" line="66" />
            <source>Control deviation out (%)</source>
            <translation>Regulační odchylka na výstupu (%)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/threshold_gain.py" line="66" />
            <source>Setpoint out (%)</source>
            <translation>Žádaná hodnota na výstupu (%)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/threshold_gain.py" line="73" />
            <source>1:1</source>
            <translation>1:1</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/diagram/dialogs/threshold_gain.py" line="75" />
            <source>output</source>
            <translation>výstup</translation>
        </message>
    </context>
    <context>
        <name>ValveConnection</name>
        <message>
            <location filename="../prm9tool/connection.py" line="117" />
            <source>The valve connection is busy; wait until it is done.</source>
            <translation>Spojení s ventilem je zaneprázdněno; počkejte na dokončení.</translation>
        </message>
        <message>
            <location filename="../prm9tool/connection.py" line="118" />
            <source>Already online; go offline first.</source>
            <translation>Již v režimu online; nejprve přejděte do režimu offline.</translation>
        </message>
        <message>
            <location filename="../prm9tool/connection.py" line="221" />
            <location filename="../prm9tool/connection.py" line="227" />
            <source>Not connected to a valve.</source>
            <translation>Není připojen žádný ventil.</translation>
        </message>
    </context>
    <context>
        <name>ValveSelectionDialog</name>
        <message>
            <location filename="../prm9tool/views/valve_selection.py" line="92" />
            <source>Valve selection</source>
            <translation>Výběr ventilu</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_selection.py" line="95" />
            <source>Choose the valve by its type key. The new parameter set holds the factory defaults of that type; valve-specific calibration data is not included.</source>
            <translation>Zvolte ventil podle typového klíče. Nový záznam parametrů obsahuje tovární nastavení tohoto typu; kalibrační údaje konkrétního ventilu v něm nejsou obsaženy.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_selection.py" line="100" />
            <source>Nominal size:</source>
            <translation>Jmenovitá světlost:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_selection.py" line="101" />
            <source>Spool:</source>
            <translation>Šoupátko:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_selection.py" line="102" />
            <source>Nominal flow (Δp 10 bar):</source>
            <translation>Jmenovitý průtok (Δp 10 bar):</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_selection.py" line="103" />
            <source>Supply voltage:</source>
            <translation>Napájecí napětí:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_selection.py" line="104" />
            <source>Configuration:</source>
            <translation>Konfigurace:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_selection.py" line="105" />
            <source>Interface:</source>
            <translation>Rozhraní:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_selection.py" line="106" />
            <source>Type key:</source>
            <translation>Typový klíč:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_selection.py" line="110" />
            <source>E02 – internal position feedback</source>
            <translation>E02 – interní polohová zpětná vazba</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_selection.py" line="111" />
            <source>E04 – internal position and external feedback</source>
            <translation>E04 – interní polohová a externí zpětná vazba</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_selection.py" line="113" />
            <source> (assumption)</source>
            <translation> (předpoklad)</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_selection.py" line="119" />
            <source>two solenoids A and B</source>
            <translation>dvě cívky A a B</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_selection.py" line="120" />
            <source>one solenoid on side {0}</source>
            <translation>jedna cívka na straně {0}</translation>
        </message>
    </context>
    <context>
        <name>ValveStatusWindow</name>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="144" />
            <source>Valve status</source>
            <translation>Stav ventilu</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="145" />
            <source>Valve</source>
            <translation>Ventil</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="146" />
            <source>Active errors</source>
            <translation>Aktivní chyby</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="147" />
            <source>LEDs</source>
            <translation>LED</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="149" />
            <source>Mode:</source>
            <translation>Režim:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="150" />
            <source>Firmware version:</source>
            <translation>Verze firmware:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="151" />
            <source>Serial number:</source>
            <translation>Výrobní číslo:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="152" />
            <source>Type key:</source>
            <translation>Typový klíč:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="153" />
            <source>Device state:</source>
            <translation>Stav zařízení:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="154" />
            <source>CANopen NMT state:</source>
            <translation>Stav NMT CANopen:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="155" />
            <source>Temperature:</source>
            <translation>Teplota:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="156" />
            <source>Supply voltage:</source>
            <translation>Napájecí napětí:</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="160" />
            <source>LED 1 power</source>
            <translation>LED 1 napájení</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="160" />
            <source>LED 2 error</source>
            <translation>LED 2 chyba</translation>
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
            <translation>Žádný stav: ventil je v režimu offline.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="216" />
            <source>white</source>
            <translation>bílá</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="217" />
            <source>green</source>
            <translation>zelená</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="218" />
            <source>orange</source>
            <translation>oranžová</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="219" />
            <source>red</source>
            <translation>červená</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="220" />
            <source>blue</source>
            <translation>modrá</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="221" />
            <source>magenta</source>
            <translation>purpurová</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="224" />
            <source>on</source>
            <translation>svítí</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="225" />
            <source>blinking 1 Hz</source>
            <translation>bliká 1 Hz</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="226" />
            <source>blinking 2 Hz</source>
            <translation>bliká 2 Hz</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="227" />
            <source>blinking 2.5 Hz</source>
            <translation>bliká 2,5 Hz</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="228" />
            <source>single flash</source>
            <translation>jednoduchý záblesk</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="229" />
            <source>double flash</source>
            <translation>dvojitý záblesk</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="230" />
            <source>triple flash</source>
            <translation>trojitý záblesk</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="231" />
            <source>quadruple flash</source>
            <translation>čtyřnásobný záblesk</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="232" />
            <source>power-up</source>
            <translation>zapínání</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="235" />
            <source>off</source>
            <translation>nesvítí</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_status.py" line="247" />
            <source>No error.</source>
            <translation>Žádná chyba.</translation>
        </message>
    </context>
    <context>
        <name>ValveWorkflow</name>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="97" />
            <source>Connecting to {0}…</source>
            <translation>Připojování k {0}…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="106" />
            <source>Store changes in the valve</source>
            <translation>Uložit změny ve ventilu</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="108" />
            <source>Values changed online are active in the valve but not stored: a restart of the valve would undo them. Store them in the valve now?</source>
            <translation>Hodnoty změněné online jsou ve ventilu aktivní, ale neuložené: restart ventilu by je vrátil. Uložit je nyní do ventilu?</translation>
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
            <translation>Čtení parametrů ventilu…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="152" />
            <source>Online: document and valve agree</source>
            <translation>Online: dokument a ventil se shodují</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="163" />
            <source>Values read from the valve</source>
            <translation>Hodnoty načtené z ventilu</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="179" />
            <source>Online: parameters read from the valve</source>
            <translation>Online: parametry načteny z ventilu</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="206" />
            <source>The valve reports an unknown type key: {0}</source>
            <translation>Ventil hlásí neznámý typový klíč: {0}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="221" />
            <source>Upload to valve</source>
            <translation>Načtení do ventilu</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="223" />
            <source>The document is for a {0} valve, the connected valve is a {1} valve. Choose the matching valve type or download the valve's parameters first.</source>
            <translation>Dokument je pro ventil {0}, připojený ventil je {1}. Zvolte odpovídající typ ventilu nebo nejprve stáhněte parametry z ventilu.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="229" />
            <source>Uploading the parameters to the valve…</source>
            <translation>Načítání parametrů do ventilu…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="234" />
            <source>Downloading the parameters from the valve…</source>
            <translation>Stahování parametrů z ventilu…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="242" />
            <source>Reset the valve's stored parameters to the factory values and restart it? Only allowed with the hydraulics disconnected.</source>
            <translation>Obnovit uložené parametry ventilu na tovární hodnoty a ventil restartovat? Dovoleno pouze při odpojeném hydraulickém obvodu.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="246" />
            <source>Set every parameter of the document to the factory default?</source>
            <translation>Nastavit všechny parametry dokumentu na tovární hodnoty?</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="251" />
            <location filename="../prm9tool/views/valve_workflow.py" line="260" />
            <source>Restore factory values</source>
            <translation>Obnovit tovární nastavení</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="262" />
            <source>Restoring the factory values…</source>
            <translation>Obnovování továrního nastavení…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="270" />
            <source>Restarting the valve…</source>
            <translation>Restartování ventilu…</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="279" />
            <source>Download from valve</source>
            <translation>Stažení z ventilu</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="281" />
            <source>Factory values of the valve</source>
            <translation>Tovární nastavení ventilu</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="283" />
            <source>The valve restarted</source>
            <translation>Ventil byl restartován</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="290" />
            <source>The valve stored its parameters</source>
            <translation>Ventil uložil své parametry</translation>
        </message>
        <message numerus="yes">
            <location filename="../prm9tool/views/valve_workflow.py" line="297" />
            <source>%n parameter(s) written, verified and stored</source>
            <translation>
                <numerusform>%n parametr zapsán, ověřen a uložen</numerusform>
                <numerusform>%n parametry zapsány, ověřeny a uloženy</numerusform>
                <numerusform>%n parametrů zapsáno, ověřeno a uloženo</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="305" />
            <source>Upload failed</source>
            <translation>Načtení do ventilu selhalo</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="307" />
            <source>The upload failed at step “{0}”. Nothing was stored: after a restart the valve holds its previous parameters.</source>
            <translation>Načtení do ventilu selhalo v kroku „{0}“. Nic nebylo uloženo: po restartu má ventil své předchozí parametry.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="324" />
            <source>Valve communication</source>
            <translation>Komunikace s ventilem</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="331" />
            <source>Connection to the valve lost</source>
            <translation>Spojení s ventilem ztraceno</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="333" />
            <source>The connection to the valve was lost; prm9tool is offline now.
Every value is kept in the document: save it, or go online again and send it.</source>
            <translation>Spojení s ventilem bylo ztraceno; prm9tool je nyní v režimu offline.
Všechny hodnoty zůstávají v dokumentu: uložte jej, nebo přejděte znovu do režimu online a odešlete jej.</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="341" />
            <source>Backup of the valve's parameters saved: {0}</source>
            <translation>Záloha parametrů ventilu uložena: {0}</translation>
        </message>
        <message>
            <location filename="../prm9tool/views/valve_workflow.py" line="348" />
            <source>Cancel</source>
            <translation>Zrušit</translation>
        </message>
    </context>
</TS>
