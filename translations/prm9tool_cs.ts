<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="cs_CZ">
    <context>
        <name>Access</name>
        <message>
            <source>{0} is a read-only value of the valve.</source>
            <translation>{0} je hodnota ventilu pouze pro čtení.</translation>
        </message>
        <message>
            <source>{0} can only be changed at Expert access level.</source>
            <translation>{0} lze změnit pouze na expertní úrovni oprávnění.</translation>
        </message>
    </context>
    <context>
        <name>App</name>
        <message>
            <source>--device {0}: no such valve</source>
            <translation>--device {0}: ventil nenalezen</translation>
        </message>
        <message>
            <source>{0}

Until the file is corrected, prm9tool knows only the spools it ships.</source>
            <translation>{0}

Dokud soubor neopravíte, zná prm9tool pouze dodaná šoupátka.</translation>
        </message>
        <message>
            <source>Spool catalogue</source>
            <translation>Katalog šoupátek</translation>
        </message>
        <message>
            <source>--emulator {0}: the serial number must be 1 … 4294967295</source>
            <translation>--emulator {0}: výrobní číslo musí být 1 … 4294967295</translation>
        </message>
        <message>
            <source>Internal error</source>
            <translation>Vnitřní chyba</translation>
        </message>
        <message>
            <source>prm9tool failed: {0}

The last action may not have been completed. Save your work under a new name and please report this error with the details below.</source>
            <translation>V prm9tool došlo k chybě: {0}

Poslední akce možná nebyla dokončena. Uložte svou práci pod novým názvem a nahlaste prosím tuto chybu s podrobnostmi níže.</translation>
        </message>
    </context>
    <context>
        <name>Autotune</name>
        <message>
            <source>The valve did not respond to the step at the present gains: the model is fitted to no response.</source>
            <translation>Ventil na skok se stávajícími zesíleními nereagoval: model je přizpůsoben nulové odezvě.</translation>
        </message>
        <message>
            <source>The model fits the measurement badly (fit error {0} %, at most {1} %).</source>
            <translation>Model špatně odpovídá měření (chyba přizpůsobení {0} %, nejvýše {1} %).</translation>
        </message>
        <message>
            <source>The proposal passes the acceptance profile “{0}” (its steps both ways and the static test).</source>
            <translation>Návrh splňuje přejímací profil „{0}“ (jeho skoky oběma směry a statickou zkoušku).</translation>
        </message>
        <message>
            <source>The proposal fails the acceptance profile “{0}”: {1}. Do not accept it unchecked.</source>
            <translation>Návrh nesplňuje přejímací profil „{0}“: {1}. Nepřebírejte jej bez kontroly.</translation>
        </message>
    </context>
    <context>
        <name>AutotunePage</name>
        <message>
            <source>Model: gain %1, lags %2 ms, dead time %3 ms (fit error %4 %).</source>
            <translation>Model: zesílení %1, zpoždění %2 ms, dopravní zpoždění %3 ms (chyba proložení %4 %).</translation>
        </message>
        <message>
            <source>Critical gain Kkr = %1, period Tkr = %2 ms: K = 0.5·Kkr, Ti = 0.8·Tkr, Td = 0.12·Tkr.</source>
            <translation>Kritické zesílení Kkr = %1, perioda Tkr = %2 ms: K = 0.5·Kkr, Ti = 0.8·Tkr, Td = 0.12·Tkr.</translation>
        </message>
        <message>
            <source>Do not accept these gains: the identification is not trustworthy.</source>
            <translation>Tato zesílení nepřebírejte: identifikace není důvěryhodná.</translation>
        </message>
        <message>
            <source>before (measured)</source>
            <translation>před (změřeno)</translation>
        </message>
        <message>
            <source>proposed (measured)</source>
            <translation>návrh (změřeno)</translation>
        </message>
        <message>
            <source>proposed (simulated)</source>
            <translation>návrh (simulováno)</translation>
        </message>
        <message>
            <source>time [ms]</source>
            <translation>čas [ms]</translation>
        </message>
        <message>
            <source>before</source>
            <translation>před</translation>
        </message>
        <message>
            <source>proposed</source>
            <translation>návrh</translation>
        </message>
        <message>
            <source>no response</source>
            <translation>bez odezvy</translation>
        </message>
        <message>
            <source>overshoot %1 %, settling %2</source>
            <translation>překmit %1 %, ustálení %2</translation>
        </message>
        <message>
            <source>%1 — before: %2; proposed: %3.</source>
            <translation>%1 — před: %2; návrh: %3.</translation>
        </message>
        <message>
            <source>steps of %1 % from 0 %, a few times</source>
            <translation>několik skoků z 0 % o %1 %</translation>
        </message>
        <message>
            <source>P only with rising gain until the loop oscillates (steps of 5 %, oscillation stopped at ±%1 %)</source>
            <translation>jen P složka s rostoucím zesílením, dokud smyčka nekmitá (skoky 5 %, kmitání zastaveno při ±%1 %)</translation>
        </message>
        <message>
            <source>; then the acceptance profile's steps of %1 % and its static test (a triangle of %2 s) with the present and the proposed gains; about %3 s in all</source>
            <translation>; potom skoky přejímacího profilu o %1 % a jeho statická zkouška (trojúhelník %2 s) se stávajícím a navrženým zesílením; celkem asi %3 s</translation>
        </message>
        <message>
            <source>Proposed, simulated on the emulator's firmware (as the controller dialog): %1.</source>
            <translation>Návrh simulovaný firmwarem emulátoru (jako v dialogu regulátoru): %1.</translation>
        </message>
        <message>
            <source>Tried before and failed the profile: %1 (%2).</source>
            <translation>Dříve zkoušeno, profil nesplněn: %1 (%2).</translation>
        </message>
        <message>
            <source>Acceptance steps of %1 %</source>
            <translation>Přejímací skoky o %1 %</translation>
        </message>
        <message>
            <source>Acceptance steps of %1 % from %2 %</source>
            <translation>Přejímací skoky o %1 % od %2 %</translation>
        </message>
        <message>
            <source>Autotune</source>
            <translation>Autotune</translation>
        </message>
        <message>
            <source>Model-based (never oscillates)</source>
            <translation>Podle modelu (nikdy nekmitá)</translation>
        </message>
        <message>
            <source>Critical gain (APOSYS 10 rule)</source>
            <translation>Kritické zesílení (pravidlo APOSYS 10)</translation>
        </message>
        <message>
            <source>Method:</source>
            <translation>Metoda:</translation>
        </message>
        <message>
            <source>Step amplitude:</source>
            <translation>Velikost skoku:</translation>
        </message>
        <message>
            <source>Target overshoot at most:</source>
            <translation>Překmit nejvýše:</translation>
        </message>
        <message>
            <source>Target settling time (±2 %) at most:</source>
            <translation>Doba ustálení (±2 %) nejvýše:</translation>
        </message>
        <message>
            <source>Stop when the response leaves 0 ± (band):</source>
            <translation>Přerušit, když odezva opustí 0 ± (pásmo):</translation>
        </message>
        <message>
            <source>Run autotune</source>
            <translation>Spustit autotune</translation>
        </message>
        <message>
            <source>Accept the proposed gains</source>
            <translation>Převzít navržené konstanty</translation>
        </message>
        <message>
            <source>Accept anyway (I checked the measurement)</source>
            <translation>Přesto převzít (měření jsem zkontroloval)</translation>
        </message>
        <message>
            <source>Figure</source>
            <translation>Ukazatel</translation>
        </message>
        <message>
            <source>Before</source>
            <translation>Před</translation>
        </message>
        <message>
            <source>Proposed</source>
            <translation>Návrh</translation>
        </message>
        <message>
            <source>Limit</source>
            <translation>Mez</translation>
        </message>
        <message>
            <source>Result</source>
            <translation>Výsledek</translation>
        </message>
    </context>
    <context>
        <name>BlockDialog</name>
        <message>
            <source>Read only: %1 (View → Access level)</source>
            <translation>Jen pro čtení: %1 (Náhled → Úroveň oprávnění)</translation>
        </message>
    </context>
    <context>
        <name>BodePage</name>
        <message>
            <source>a sine sweep %1 … %2 Hz of ±%3 % around %4 %, %5 s</source>
            <translation>rozmítaný sinus %1 … %2 Hz o ±%3 % kolem %4 %, %5 s</translation>
        </message>
        <message>
            <source>above %1 Hz</source>
            <translation>nad %1 Hz</translation>
        </message>
        <message>
            <source>not reached</source>
            <translation>nedosaženo</translation>
        </message>
        <message>
            <source>−3 dB: %1, −90°: %2.</source>
            <translation>−3 dB: %1, −90°: %2.</translation>
        </message>
        <message>
            <source>%1 of %2 samples were lost on the link and left out of the estimate.</source>
            <translation>%1 z %2 vzorků se na spojení ztratilo a do odhadu nebyly zahrnuty.</translation>
        </message>
        <message>
            <source>The PC held the valve's setpoint for %1 ms at %2 Hz: the sweep counts up to there (at least 4 setpoint changes per period).</source>
            <translation>Počítač držel žádanou hodnotu ventilu při %2 Hz po %1 ms: rozmítání platí jen do tohoto místa (nejméně 4 změny žádané hodnoty za periodu).</translation>
        </message>
        <message>
            <source>Amplitude:</source>
            <translation>Amplituda:</translation>
        </message>
        <message>
            <source>Operating point:</source>
            <translation>Pracovní bod:</translation>
        </message>
        <message>
            <source>From:</source>
            <translation>Od:</translation>
        </message>
        <message>
            <source>To:</source>
            <translation>Do:</translation>
        </message>
        <message>
            <source>Duration:</source>
            <translation>Doba trvání:</translation>
        </message>
        <message>
            <source>Measure the frequency response</source>
            <translation>Změřit frekvenční charakteristiku</translation>
        </message>
        <message>
            <source>The link's sample rate limited the sweep to %1 Hz (nothing interpolated).</source>
            <translation>Vzorkovací frekvence spojení omezila rozmítání na %1 Hz (nic nebylo interpolováno).</translation>
        </message>
    </context>
    <context>
        <name>BusLssActions</name>
        <message>
            <source>Find bit rate</source>
            <translation>Zjistit přenosovou rychlost</translation>
        </message>
        <message>
            <source>Listen at each bit rate in listen-only mode (nothing is sent)</source>
            <translation>Naslouchat při každé přenosové rychlosti v režimu pouze poslech (nic se neodesílá)</translation>
        </message>
        <message>
            <source>Change node ID by LSS…</source>
            <translation>Změnit Node ID pomocí LSS…</translation>
        </message>
        <message>
            <source>Change bit rate by LSS…</source>
            <translation>Změnit přenosovou rychlost pomocí LSS…</translation>
        </message>
        <message>
            <source>Listening at each bit rate (listen-only: nothing is sent)…</source>
            <translation>Naslouchá se při každé přenosové rychlosti (pouze poslech: nic se neodesílá)…</translation>
        </message>
        <message>
            <source>none identified</source>
            <translation>žádný nerozpoznán</translation>
        </message>
        <message>
            <source>The bus runs at {0} kbit/s (frames from nodes: {1}). Search the bus.</source>
            <translation>Sběrnice běží rychlostí {0} kbit/s (rámce od uzlů: {1}). Prohledejte sběrnici.</translation>
        </message>
        <message>
            <source>Change node ID by LSS</source>
            <translation>Změnit Node ID pomocí LSS</translation>
        </message>
        <message>
            <source>New node ID for serial {0}, now {1} (1…127):</source>
            <translation>Nové Node ID pro sériové číslo {0}, nyní {1} (1…127):</translation>
        </message>
        <message>
            <source>Node ID {0} is taken: a node answers there. Choose another one.</source>
            <translation>Node ID {0} je obsazené: na něm odpovídá uzel. Zvolte jiné.</translation>
        </message>
        <message>
            <source>Serial {0} will answer at node {2} instead of {1}, stored in the valve (its node-ID switch must be at 1: LSS). prm9tool's own link moves with it: a connection to can:{1} ends, and prm9tool goes online with can:{2}. A PLC that addresses node {1} no longer reaches the valve. Change it?</source>
            <translation>Sériové číslo {0} pak odpovídá jako uzel {2} místo {1}, uloženo ve ventilu (jeho přepínač Node ID musí být v poloze 1: LSS). Vlastní spojení prm9tool se přesune s ním: spojení s can:{1} skončí a prm9tool přejde do režimu online s can:{2}. PLC, které adresuje uzel {1}, ventil již nezastihne. Změnit?</translation>
        </message>
        <message>
            <source>Changing the node ID of serial {0} to {1}…</source>
            <translation>Node ID sériového čísla {0} se mění na {1}…</translation>
        </message>
        <message>
            <source>Change bit rate by LSS</source>
            <translation>Změnit přenosovou rychlost pomocí LSS</translation>
        </message>
        <message>
            <source>New bit rate of the bus:</source>
            <translation>Nová přenosová rychlost sběrnice:</translation>
        </message>
        <message>
            <source>Every valve at node-ID switch 1 (LSS) switches from {1} kbit/s to {0} kbit/s together and stores it. Nodes whose switches set the bit rate (node-ID switch 0 or 2…F) and the PLC keep {1} kbit/s: set them too before the machine runs again, or the bus stops working. prm9tool's own link moves to {0} kbit/s. Change the bit rate?</source>
            <translation>Všechny ventily s přepínačem Node ID v poloze 1 (LSS) přejdou společně z {1} kbit/s na {0} kbit/s a uloží to. Uzly, jejichž přepínače určují přenosovou rychlost (přepínač Node ID 0 nebo 2…F), a PLC zůstanou na {1} kbit/s: přestavte je také, než stroj znovu poběží, jinak sběrnice přestane fungovat. Vlastní spojení prm9tool přejde na {0} kbit/s. Změnit přenosovou rychlost?</translation>
        </message>
        <message>
            <source>Changing the bit rate to {0} kbit/s by LSS…</source>
            <translation>Přenosová rychlost se mění pomocí LSS na {0} kbit/s…</translation>
        </message>
        <message>
            <source>{0} valve(s) switched to {1} kbit/s. prm9tool cannot change the bit rate of a socketcan interface: sudo ip link set {2} down &amp;&amp; sudo ip link set {2} up type can bitrate {3}, then search the bus.</source>
            <translation>Ventily přepnuté na {1} kbit/s: {0}. prm9tool nemůže změnit přenosovou rychlost rozhraní socketcan: sudo ip link set {2} down &amp;&amp; sudo ip link set {2} up type can bitrate {3}, pak prohledejte sběrnici.</translation>
        </message>
        <message>
            <source>{0} valve(s) switched to {1} kbit/s; prm9tool follows.</source>
            <translation>Ventily přepnuté na {1} kbit/s: {0}; prm9tool je následuje.</translation>
        </message>
    </context>
    <context>
        <name>CanBusDialog</name>
        <message>
            <source>CAN bus</source>
            <translation>Sběrnice CAN</translation>
        </message>
        <message>
            <source>Search the bus</source>
            <translation>Prohledat sběrnici</translation>
        </message>
        <message>
            <source>Search the bus to list its nodes.</source>
            <translation>Prohledejte sběrnici, aby se vypsaly její uzly.</translation>
        </message>
        <message>
            <source>Node</source>
            <translation>Uzel</translation>
        </message>
        <message>
            <source>Type key</source>
            <translation>Objednací kód</translation>
        </message>
        <message>
            <source>Serial</source>
            <translation>Výrobní číslo</translation>
        </message>
        <message>
            <source>Firmware</source>
            <translation>Firmware</translation>
        </message>
        <message>
            <source>NMT state</source>
            <translation>Stav NMT</translation>
        </message>
        <message>
            <source>Heartbeat</source>
            <translation>Heartbeat</translation>
        </message>
        <message>
            <source>Last EMCY</source>
            <translation>Poslední EMCY</translation>
        </message>
        <message>
            <source>Description</source>
            <translation>Popis</translation>
        </message>
        <message>
            <source>Interface (python-can)</source>
            <translation>Rozhraní (python-can)</translation>
        </message>
        <message>
            <source>Channel</source>
            <translation>Kanál</translation>
        </message>
        <message>
            <source>Bit rate</source>
            <translation>Přenosová rychlost</translation>
        </message>
        <message>
            <source>as the adapter is set</source>
            <translation>jak je nastaven adaptér</translation>
        </message>
        <message>
            <source>Online with {0} on this bus: the nodes are shown as they tell about themselves (nothing is sent). Go offline to search the bus or to choose another valve.</source>
            <translation>Online s {0} na této sběrnici: uzly se zobrazují tak, jak o sobě samy dávají vědět (nic se neodesílá). Chcete-li sběrnici prohledat nebo zvolit jiný ventil, přejděte do režimu offline.</translation>
        </message>
        <message>
            <source>Online with {0}: search the bus to watch its nodes; go offline to go online with one of them.</source>
            <translation>Online s {0}: prohledejte sběrnici a sledujte její uzly; chcete-li se připojit k některému z nich, přejděte nejprve do režimu offline.</translation>
        </message>
        <message>
            <source>Searching the bus (node IDs 1…127)…</source>
            <translation>Prohledává se sběrnice (ID uzlů 1…127)…</translation>
        </message>
        <message>
            <source>The bus could not be searched: {0}</source>
            <translation>Sběrnici nelze prohledat: {0}</translation>
        </message>
        <message numerus="yes">
            <source>%n node(s) answered.</source>
            <translation>
                <numerusform>Odpověděl %n uzel.</numerusform>
                <numerusform>Odpověděly %n uzly.</numerusform>
                <numerusform>Odpovědělo %n uzlů.</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n of them PRM9 valve(s).</source>
            <translation>
                <numerusform>Z toho %n ventil PRM9.</numerusform>
                <numerusform>Z toho %n ventily PRM9.</numerusform>
                <numerusform>Z toho %n ventilů PRM9.</numerusform>
            </translation>
        </message>
        <message>
            <source>not identified</source>
            <translation>neidentifikováno</translation>
        </message>
        <message>
            <source>not a PRM9</source>
            <translation>není PRM9</translation>
        </message>
        <message>
            <source>{0:.1f} s ago</source>
            <translation>před {0:.1f} s</translation>
        </message>
        <message>
            <source>none</source>
            <translation>žádný</translation>
        </message>
        <message>
            <source>new on the bus: search again to identify it</source>
            <translation>nový na sběrnici: pro rozpoznání hledejte znovu</translation>
        </message>
        <message>
            <source>the valve prm9tool is online with</source>
            <translation>ventil, se kterým je prm9tool online</translation>
        </message>
        <message>
            <source>heard on the bus</source>
            <translation>slyšen na sběrnici</translation>
        </message>
        <message>
            <source>{0} (boot-up {1:.1f} s ago)</source>
            <translation>{0} (boot-up před {1:.1f} s)</translation>
        </message>
        <message>
            <source>silent for {0:.1f} s</source>
            <translation>mlčí {0:.1f} s</translation>
        </message>
        <message>
            <source>The bus cannot be watched: {0}</source>
            <translation>Sběrnici nelze sledovat: {0}</translation>
        </message>
        <message>
            <source>The valve (serial number {0}) does not tell its type key, and its objects do not tell E02 from E04 (-CA). Type key on the valve's label:</source>
            <translation>Ventil (výrobní číslo {0}) neuvádí svůj typový klíč a jeho objekty nerozliší E02 od E04 (-CA). Typový klíč ze štítku ventilu:</translation>
        </message>
        <message>
            <source>Type key of the valve</source>
            <translation>Objednací kód ventilu</translation>
        </message>
        <message>
            <source>The valve (serial number {0}) does not tell its type key; its objects say {1} -CA. Type key on the valve's label:</source>
            <translation>Ventil (výrobní číslo {0}) neudává svůj objednací kód; jeho objekty říkají {1} -CA. Objednací kód ze štítku ventilu:</translation>
        </message>
        <message>
            <source>{0} does not fit the valve: its objects say {1} -CA.</source>
            <translation>{0} neodpovídá ventilu: jeho objekty říkají {1} -CA.</translation>
        </message>
    </context>
    <context>
        <name>CanLink</name>
        <message>
            <source>CANopen: prm9tool abandoned an SDO transfer: {0} (abort code {1})</source>
            <translation>CANopen: prm9tool přerušil přenos SDO: {0} (kód přerušení {1})</translation>
        </message>
        <message>
            <source>CANopen: the node did not answer an SDO request in time; asking again</source>
            <translation>CANopen: Uzel neodpověděl na požadavek SDO včas; požadavek se opakuje</translation>
        </message>
        <message>
            <source>CANopen: receiving stopped after an error of the CAN interface; go offline and connect again</source>
            <translation>CANopen: Po chybě rozhraní CAN se příjem zastavil; přejděte do režimu offline a připojte se znovu</translation>
        </message>
        <message>
            <source>CANopen: a received frame could not be processed: {0}</source>
            <translation>CANopen: Přijatou zprávu nelze zpracovat: {0}</translation>
        </message>
        <message>
            <source>CAN interface ({0}): {1}</source>
            <translation>Rozhraní CAN ({0}): {1}</translation>
        </message>
    </context>
    <context>
        <name>CanNodeText</name>
        <message>
            <source>{0} channel {1}</source>
            <translation>{0} kanál {1}</translation>
        </message>
        <message>
            <source>, {0} bit/s</source>
            <translation>, {0} bit/s</translation>
        </message>
        <message>
            <source>CANopen node {0} on {1}: {2}</source>
            <translation>Uzel CANopen {0} na {1}: {2}</translation>
        </message>
        <message>
            <source>Node {0} does not answer as a CANopen node: {1}</source>
            <translation>Uzel {0} neodpovídá jako uzel CANopen: {1}</translation>
        </message>
        <message>
            <source>Node {0} could not be identified: {1}</source>
            <translation>Uzel {0} se nepodařilo identifikovat: {1}</translation>
        </message>
        <message>
            <source>none</source>
            <translation>žádný</translation>
        </message>
        <message>
            <source>Node {0}: not a PRM9 (device type 0x{1:X}, vendor {2})</source>
            <translation>Uzel {0}: není PRM9 (typ zařízení 0x{1:X}, výrobce {2})</translation>
        </message>
    </context>
    <context>
        <name>CanopenWindow</name>
        <message>
            <source>CANopen</source>
            <translation>CANopen</translation>
        </message>
        <message>
            <source>The valve reads its two rotary switches at power-up only; the marked rows are the positions it read at its last start. Terminator, node ID and bit rate set here are stored in the valve and take effect after the next restart.</source>
            <translation>Ventil čte své dva otočné přepínače pouze při zapnutí; označené řádky jsou polohy načtené při posledním spuštění. Zde nastavený terminátor, Node ID a přenosová rychlost se uloží do ventilu a platí po dalším restartu.</translation>
        </message>
        <message>
            <source>Interface / bit-rate switch</source>
            <translation>Přepínač rozhraní / přenosové rychlosti</translation>
        </message>
        <message>
            <source>Node-ID switch</source>
            <translation>Přepínač Node ID</translation>
        </message>
        <message>
            <source>Settings made by software (USB)</source>
            <translation>Nastavení softwarem (USB)</translation>
        </message>
        <message>
            <source>Position</source>
            <translation>Poloha</translation>
        </message>
        <message>
            <source>Interface / bit rate</source>
            <translation>Rozhraní / přenosová rychlost</translation>
        </message>
        <message>
            <source>Terminator</source>
            <translation>Terminátor</translation>
        </message>
        <message>
            <source>Node ID</source>
            <translation>Node ID</translation>
        </message>
        <message>
            <source>CAN terminator 120 Ω</source>
            <translation>Terminátor CAN 120 Ω</translation>
        </message>
        <message>
            <source>Node ID (node switch at 0)</source>
            <translation>Node ID (přepínač Node ID v poloze 0)</translation>
        </message>
        <message>
            <source>Bit rate (node switch at 0)</source>
            <translation>Přenosová rychlost (přepínač Node ID v poloze 0)</translation>
        </message>
        <message>
            <source>on</source>
            <translation>zapnutý</translation>
        </message>
        <message>
            <source>Overridden: with the node-ID switch at 1 the interface switch has no function; the terminator follows the software setting below.</source>
            <translation>Neplatí: s přepínačem Node ID v poloze 1 nemá přepínač rozhraní žádnou funkci; terminátor se řídí nastavením softwaru níže.</translation>
        </message>
        <message>
            <source>Overridden: with the node-ID switch at 1 (LSS) the valve detects the bit rate of the bus.</source>
            <translation>Neplatí: s přepínačem Node ID v poloze 1 (LSS) ventil rozpozná přenosovou rychlost sběrnice.</translation>
        </message>
        <message>
            <source>Overridden: with the node-ID switch at 0 the bit rate set by software below applies.</source>
            <translation>Neplatí: s přepínačem Node ID v poloze 0 platí přenosová rychlost nastavená softwarem níže.</translation>
        </message>
        <message>
            <source>CANopen off, analog setpoint only</source>
            <translation>CANopen vypnuto, pouze analogová žádaná hodnota</translation>
        </message>
        <message>
            <source>reserved (as position 0)</source>
            <translation>rezervováno (jako poloha 0)</translation>
        </message>
        <message>
            <source>off (on by software)</source>
            <translation>vypnutý (zapnutí softwarem)</translation>
        </message>
        <message>
            <source>CANopen, %1</source>
            <translation>CANopen, %1</translation>
        </message>
        <message>
            <source>set by software: 1 … 127 (below)</source>
            <translation>nastavení softwarem: 1 … 127 (níže)</translation>
        </message>
        <message>
            <source>LSS, automatic bit rate</source>
            <translation>LSS, automatická přenosová rychlost</translation>
        </message>
        <message>
            <source>Position read by the valve at its last power-up</source>
            <translation>Poloha načtená ventilem při posledním zapnutí</translation>
        </message>
        <message>
            <source>Settings made by software (over CANopen)</source>
            <translation>Nastavení softwarem (přes CANopen)</translation>
        </message>
        <message>
            <source>Settings made by software</source>
            <translation>Nastavení softwarem</translation>
        </message>
        <message>
            <source>The node-ID switch is not at 0: the switch sets the node ID.</source>
            <translation>Přepínač Node ID není v poloze 0: Node ID určuje přepínač.</translation>
        </message>
        <message>
            <source>This valve type has no CANopen interface (no -CA in the type key).</source>
            <translation>Tento typ ventilu nemá rozhraní CANopen (typový klíč bez -CA).</translation>
        </message>
        <message>
            <source>Offline: the switch positions are unknown. Settings changed here go into the document; upload it to the valve and restart the valve.</source>
            <translation>Offline: polohy přepínačů nejsou známé. Zde změněná nastavení se uloží do dokumentu; načtěte jej do ventilu a ventil restartujte.</translation>
        </message>
        <message>
            <source>Reading the switch positions from the valve …</source>
            <translation>Čtení poloh přepínačů z ventilu …</translation>
        </message>
        <message>
            <source>Switch positions read from the valve at its last power-up.</source>
            <translation>Polohy přepínačů načtené ventilem při posledním zapnutí.</translation>
        </message>
        <message>
            <source>automatic bit rate</source>
            <translation>automatická přenosová rychlost</translation>
        </message>
        <message>
            <source>The node-ID switch is at 0: node ID and bit rate are the ones set below (the interface switch's bit rate is struck through); its positions 9…F still switch the terminator on.</source>
            <translation>Přepínač Node ID je v poloze 0: Node ID a přenosová rychlost jsou ty nastavené níže (přenosová rychlost přepínače rozhraní je přeškrtnutá); jeho polohy 9…F přesto zapínají terminátor.</translation>
        </message>
        <message>
            <source>The node-ID switch is at 1 (LSS, automatic bit rate): the interface switch has no function, the terminator follows the setting below.</source>
            <translation>Přepínač Node ID je v poloze 1 (LSS, automatická přenosová rychlost): přepínač rozhraní nemá žádnou funkci, terminátor se řídí nastavením níže.</translation>
        </message>
        <message>
            <source>After the next restart the valve uses:</source>
            <translation>Po dalším restartu ventil použije:</translation>
        </message>
        <message>
            <source>The valve uses:</source>
            <translation>Ventil používá:</translation>
        </message>
        <message>
            <source>CANopen off (analog setpoint only).</source>
            <translation>CANopen vypnuto (pouze analogová žádaná hodnota).</translation>
        </message>
        <message>
            <source>off</source>
            <translation>vypnutý</translation>
        </message>
        <message>
            <source>node ID %1, %2, terminator %3.</source>
            <translation>Node ID %1, %2, terminátor %3.</translation>
        </message>
        <message>
            <source>Changed in the document; the valve does not follow the document now. Upload it to the valve; the change takes effect after the valve restarts.</source>
            <translation>Změněno v dokumentu; ventil teď dokument nenásleduje. Načtěte jej do ventilu; změna se projeví po restartu ventilu.</translation>
        </message>
        <message>
            <source>Changed in the document. Upload it to the valve; the change takes effect after the valve restarts.</source>
            <translation>Změněno v dokumentu. Načtěte jej do ventilu; změna se projeví po restartu ventilu.</translation>
        </message>
        <message>
            <source>Written to the valve and stored. The change takes effect after the valve restarts (Valve → Restart valve).</source>
            <translation>Zapsáno do ventilu a uloženo. Změna se projeví po restartu ventilu (Ventil → Restart ventilu).</translation>
        </message>
    </context>
    <context>
        <name>ChangePasswordDialog</name>
        <message>
            <source>Change Expert password</source>
            <translation>Změna hesla pro expertní úroveň</translation>
        </message>
        <message>
            <source>Current password:</source>
            <translation>Současné heslo:</translation>
        </message>
        <message>
            <source>New password:</source>
            <translation>Nové heslo:</translation>
        </message>
        <message>
            <source>Repeat new password:</source>
            <translation>Nové heslo znovu:</translation>
        </message>
        <message>
            <source>The current password is wrong.</source>
            <translation>Současné heslo je chybné.</translation>
        </message>
        <message>
            <source>The new password must have at least {0} characters.</source>
            <translation>Nové heslo musí mít alespoň {0} znaky.</translation>
        </message>
        <message>
            <source>The two new passwords differ.</source>
            <translation>Obě nová hesla se liší.</translation>
        </message>
    </context>
    <context>
        <name>ChannelPanel</name>
        <message>
            <source>Measuring points</source>
            <translation>Měřicí body</translation>
        </message>
        <message>
            <source>At most three measuring points: {0} replaces {1}.</source>
            <translation>Nejvýše tři měřicí body: {0} nahrazuje {1}.</translation>
        </message>
        <message>
            <source>At most three measuring points can be recorded at once. Switch one off before adding {0}.</source>
            <translation>Současně lze zaznamenávat nejvýše tři měřicí body. Před přidáním {0} jeden vypněte.</translation>
        </message>
        <message>
            <source>Autoscaled channels with the same unit share one scale and one axis</source>
            <translation>Automaticky škálované kanály se stejnou jednotkou sdílejí jedno měřítko a jednu osu</translation>
        </message>
        <message>
            <source>Same scale per unit</source>
            <translation>Stejné měřítko pro jednotku</translation>
        </message>
    </context>
    <context>
        <name>Characterize</name>
        <message>
            <source>the model-based autotune needs the controller's output, which this link does not sample (CANopen); use the critical-gain method</source>
            <translation>automatické ladění podle modelu potřebuje výstup regulátoru, který toto spojení nevzorkuje (CANopen); použijte metodu kritického zesílení</translation>
        </message>
        <message>
            <source>no gains found for the target: {0}</source>
            <translation>pro zadaný cíl nebyla nalezena žádná zesílení: {0}</translation>
        </message>
        <message>
            <source>stopped by the user; the valve was put back as it was</source>
            <translation>zastaveno uživatelem; ventil byl vrácen do původního stavu</translation>
        </message>
        <message>
            <source>the valve reported error {0}: {1}</source>
            <translation>ventil hlásil chybu {0}: {1}</translation>
        </message>
        <message>
            <source>the valve reports error {0} ({1}); nothing was tested</source>
            <translation>ventil hlásí chybu {0} ({1}); nic nebylo testováno</translation>
        </message>
        <message>
            <source>the valve does not follow its setpoint: device state {0} (a -CA valve with CANopen on waits for its master to enable it); nothing was tested</source>
            <translation>ventil nesleduje svou žádanou hodnotu: stav zařízení {0} (ventil -CA se zapnutým CANopen čeká, až ho jeho master uvolní); nic nebylo testováno</translation>
        </message>
        <message>
            <source>the valve does not follow its setpoint: device state {0}; nothing was tested</source>
            <translation>ventil nesleduje svou žádanou hodnotu: stav zařízení {0}; nic nebylo testováno</translation>
        </message>
        <message>
            <source>the valve did not finish booting</source>
            <translation>ventil nedokončil start</translation>
        </message>
        <message>
            <source>flow characteristic not measured: this valve has no object for {0} over this link (measure it over USB)</source>
            <translation>Průtoková charakteristika nebyla změřena: ventil nemá po tomto spojení objekt pro {0} (změřte ji přes USB)</translation>
        </message>
        <message>
            <source>the flow characteristic is measured on E04 valves (with an actuator)</source>
            <translation>průtoková charakteristika se měří na ventilech E04 (s akčním členem)</translation>
        </message>
        <message>
            <source>this valve has no object for the process controller's gains on this link: the flow characteristic (made proportional for the test) cannot be measured here; nothing was changed — measure it over USB</source>
            <translation>tento ventil nemá na tomto spojení objekt pro zesílení regulátoru procesu: průtokovou charakteristiku (pro test proporcionální) zde nelze změřit; nic nebylo změněno — změřte ji přes USB</translation>
        </message>
        <message>
            <source>the flow characteristic is measured in control mode 4 (process loop); the valve is in control mode {0}</source>
            <translation>průtoková charakteristika se měří v režimu řízení 4 (procesní smyčka); ventil je v režimu řízení {0}</translation>
        </message>
        <message>
            <source>the process controller's Kp is 0: the spool would not move</source>
            <translation>Kp procesního regulátoru je 0: šoupátko by se nepohnulo</translation>
        </message>
        <message>
            <source>this valve has no object for {0} on this link (their addresses are this project's, not the manual's): the tuning cannot change them here; nothing was changed — tune these over USB</source>
            <translation>tento ventil nemá na tomto spojení objekt pro {0} (jejich adresy jsou adresami tohoto projektu, ne příručky): ladění je zde nemůže změnit; nic nebylo změněno — nalaďte je přes USB</translation>
        </message>
        <message>
            <source>the valve is in control mode {0} (spool position): it has no process loop to test; the process loop runs in control mode 4 (CTRLMODE). Nothing was changed</source>
            <translation>ventil je v režimu řízení {0} (poloha šoupátka): nemá procesní smyčku, kterou by šlo testovat; procesní smyčka pracuje v režimu řízení 4 (CTRLMODE). Nic nebylo změněno</translation>
        </message>
        <message>
            <source>the valve is in control mode {0} (process loop): its setpoint drives the process controller, not the spool, so the position loop cannot be tested on its own. Choose the process loop, or set CTRLMODE to 2 (spool position) while the valve is not enabled. Nothing was changed</source>
            <translation>ventil je v režimu řízení {0} (procesní smyčka): jeho žádaná hodnota řídí regulátor procesu, ne šoupátko, takže smyčku polohy nelze testovat samostatně. Zvolte procesní smyčku, nebo nastavte CTRLMODE na 2 (poloha šoupátka), dokud ventil není povolen. Nic nebylo změněno</translation>
        </message>
        <message>
            <source>{0} left the allowed band {1} ± {2} %; the test was stopped and the valve put back as it was</source>
            <translation>{0}: hodnota opustila povolené pásmo {1} ± {2} %; test byl zastaven a ventil uveden do původního stavu</translation>
        </message>
        <message>
            <source>sweep limited to {0} Hz (of {1} Hz asked) by the link's sample rate of {2} Hz</source>
            <translation>rozmítání omezeno na {0} Hz (požadováno {1} Hz) vzorkovací frekvencí spojení {2} Hz</translation>
        </message>
        <message>
            <source>sweep usable up to {0} Hz: the PC held the valve's setpoint for {1} ms there (at least {2} updates per period are needed; the PC was busy)</source>
            <translation>rozmítání použitelné do {0} Hz: počítač tam držel žádanou hodnotu ventilu {1} ms (je třeba nejméně {2} aktualizací za periodu; počítač byl vytížen)</translation>
        </message>
        <message>
            <source>frequency response: {0} of {1} samples lost on the link, left out of the estimate</source>
            <translation>frekvenční charakteristika: {0} z {1} vzorků ztraceno na spojení, vynecháno z odhadu</translation>
        </message>
        <message>
            <source>the history holds no end-of-line test of serial {0} ({1}) to compare with: make its birth certificate first — run the end-of-line test on this valve (Tuning window → Test report → Run the end-of-line test, online; or prm9tool --characterize --device ID --report OUT.pdf) with the history on; nothing was moved</source>
            <translation>historie neobsahuje žádnou výstupní zkoušku výrobního čísla {0} ({1}) k porovnání: nejprve vytvořte jeho rodný list — proveďte na tomto ventilu výstupní zkoušku (okno Ladění a charakterizace → Protokol o zkoušce → Spustit výstupní zkoušku, online; nebo prm9tool --characterize --device ID --report OUT.pdf) se zapnutou historií; nic se nepohnulo</translation>
        </message>
        <message>
            <source>the birth certificate is kept in the history, which is off for this valve: open it with the history on; nothing was moved</source>
            <translation>rodný list je uložen v historii, která je pro tento ventil vypnutá: otevřete jej se zapnutou historií; nic se nepohnulo</translation>
        </message>
    </context>
    <context>
        <name>CommissioningPanel</name>
        <message>
            <source>Commissioning</source>
            <translation>Uvedení do provozu</translation>
        </message>
        <message>
            <source>Enable</source>
            <translation>Uvolnit</translation>
        </message>
        <message>
            <source>Control word 0x6040: 08h → 09h → 0Bh → 0Fh (manual §7.6): resets a fault, then DISABLED, HOLD, DEVICE_MODE_ACTIVE. The valve follows its setpoint.</source>
            <translation>Řídicí slovo 0x6040: 08h → 09h → 0Bh → 0Fh (návod §7.6): resetuje chybu, pak DISABLED, HOLD, DEVICE_MODE_ACTIVE. Ventil sleduje svou žádanou hodnotu.</translation>
        </message>
        <message>
            <source>Disable</source>
            <translation>Zablokovat</translation>
        </message>
        <message>
            <source>Control word 0x6040: 0Fh → 0Bh → 09h → 08h, back to INIT.</source>
            <translation>Řídicí slovo 0x6040: 0Fh → 0Bh → 09h → 08h, zpět do INIT.</translation>
        </message>
        <message>
            <source>NMT start</source>
            <translation>NMT start</translation>
        </message>
        <message>
            <source>NMT start: operational (PDOs run)</source>
            <translation>NMT start: operational (PDO běží)</translation>
        </message>
        <message>
            <source>NMT pre-operational</source>
            <translation>NMT pre-operational</translation>
        </message>
        <message>
            <source>NMT enter pre-operational</source>
            <translation>NMT: přejít do pre-operational</translation>
        </message>
        <message>
            <source>NMT stop</source>
            <translation>NMT stop</translation>
        </message>
        <message>
            <source>NMT stop: only NMT is answered</source>
            <translation>NMT stop: odpovídá jen na NMT</translation>
        </message>
        <message>
            <source>The valve follows its setpoint (DEVICE_MODE_ACTIVE).</source>
            <translation>Ventil sleduje svou žádanou hodnotu (DEVICE_MODE_ACTIVE).</translation>
        </message>
        <message>
            <source>The valve does not follow its setpoint: {0}</source>
            <translation>Ventil nesleduje svou žádanou hodnotu: {0}</translation>
        </message>
    </context>
    <context>
        <name>Compare</name>
        <message>
            <source>The type keys differ: {0} is {1}, {2} is {3}.</source>
            <translation>Typové klíče se liší: {0} je {1}, {2} je {3}.</translation>
        </message>
        <message>
            <source>The valve variants differ: only the parameters both have are compared; {0} parameters that one side lacks are left out.</source>
            <translation>Varianty ventilů se liší: porovnávají se jen parametry, které mají obě strany; {0} parametrů, které jedné straně chybí, je vynecháno.</translation>
        </message>
        <message>
            <source>not on this valve</source>
            <translation>ve ventilu není</translation>
        </message>
        <message>
            <source>not on the valve it was read from</source>
            <translation>není ve ventilu, ze kterého byl načten</translation>
        </message>
    </context>
    <context>
        <name>CompareDialog</name>
        <message>
            <source>Compare parameters</source>
            <translation>Porovnání parametrů</translation>
        </message>
        <message>
            <source>Differences only</source>
            <translation>Jen rozdíly</translation>
        </message>
        <message>
            <source>All blocks</source>
            <translation>Všechny bloky</translation>
        </message>
        <message>
            <source>Basic level</source>
            <translation>Základní úroveň</translation>
        </message>
        <message>
            <source>Expert level</source>
            <translation>Expertní úroveň</translation>
        </message>
        <message>
            <source>Block:</source>
            <translation>Blok:</translation>
        </message>
        <message>
            <source>Access level:</source>
            <translation>Úroveň oprávnění:</translation>
        </message>
        <message>
            <source>Tick every shown value of {0}</source>
            <translation>Označit všechny zobrazené hodnoty „{0}“</translation>
        </message>
        <message>
            <source>Close</source>
            <translation>Zavřít</translation>
        </message>
        <message numerus="yes">
            <source>Write %n ticked value(s) into the valve</source>
            <translation>
                <numerusform>Zapsat %n označenou hodnotu do ventilu</numerusform>
                <numerusform>Zapsat %n označené hodnoty do ventilu</numerusform>
                <numerusform>Zapsat %n označených hodnot do ventilu</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>Take %n ticked value(s) into the document</source>
            <translation>
                <numerusform>Převzít %n označenou hodnotu do dokumentu</numerusform>
                <numerusform>Převzít %n označené hodnoty do dokumentu</numerusform>
                <numerusform>Převzít %n označených hodnot do dokumentu</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>Copy %n ticked value(s) into “{0}”</source>
            <translation>
                <numerusform>Zkopírovat %n označenou hodnotu do „{0}“</numerusform>
                <numerusform>Zkopírovat %n označené hodnoty do „{0}“</numerusform>
                <numerusform>Zkopírovat %n označených hodnot do „{0}“</numerusform>
            </translation>
        </message>
        <message>
            <source>Every row starts with the valve's value ticked. Tick the document's value where the document is right, then press Apply: the document takes the ticked valve values and the valve the ticked document values.</source>
            <translation>V každém řádku je nejprve označena hodnota ventilu. Kde je správná hodnota dokumentu, označte ji a pak stiskněte „Použít“: dokument převezme označené hodnoty ventilu a ventil označené hodnoty dokumentu.</translation>
        </message>
        <message>
            <source>Tick the values to take, in either column; then take them into the document, or write them into the valve (online with this valve).</source>
            <translation>Označte požadované hodnoty v kterémkoli sloupci; pak je převezměte do dokumentu nebo zapište do ventilu (v režimu online s tímto ventilem).</translation>
        </message>
        <message>
            <source>Shown for comparison only.</source>
            <translation>Zobrazeno jen pro porovnání.</translation>
        </message>
        <message>
            <source>Apply: each side takes the ticked values</source>
            <translation>Použít: každá strana převezme označené hodnoty</translation>
        </message>
        <message>
            <source>Tick values in the column “{0}” first</source>
            <translation>Nejprve označte hodnoty ve sloupci „{0}“</translation>
        </message>
        <message numerus="yes">
            <source>%n parameter(s) differ</source>
            <translation>
                <numerusform>%n parametr se liší</numerusform>
                <numerusform>%n parametry se liší</numerusform>
                <numerusform>%n parametrů se liší</numerusform>
            </translation>
        </message>
        <message>
            <source>To write values into the valve: tick them in the column “{0}”, then press the button below.</source>
            <translation>Zápis hodnot do ventilu: označte je ve sloupci „{0}“ a stiskněte tlačítko dole.</translation>
        </message>
        <message>
            <source>To take values into the document: tick them in the column “{0}”, then press the button below.</source>
            <translation>Převzetí hodnot do dokumentu: označte je ve sloupci „{0}“ a stiskněte tlačítko dole.</translation>
        </message>
        <message>
            <source>To copy values into “{0}”: tick them in the column “{1}”, then press the button below.</source>
            <translation>Kopírování hodnot do „{0}“: označte je ve sloupci „{1}“ a stiskněte tlačítko dole.</translation>
        </message>
        <message numerus="yes">
            <source>%n parameter(s) only on one side</source>
            <translation>
                <numerusform>%n parametr jen na jedné straně</numerusform>
                <numerusform>%n parametry jen na jedné straně</numerusform>
                <numerusform>%n parametrů jen na jedné straně</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n parameter(s) not on the valve, not compared</source>
            <translation>
                <numerusform>%n parametr není ve ventilu, neporovnán</numerusform>
                <numerusform>%n parametry nejsou ve ventilu, neporovnány</numerusform>
                <numerusform>%n parametrů není ve ventilu, neporovnáno</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n shown</source>
            <translation>
                <numerusform>%n zobrazen</numerusform>
                <numerusform>%n zobrazeny</numerusform>
                <numerusform>%n zobrazeno</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>CompareTableModel</name>
        <message>
            <source>Mnemonic</source>
            <translation>Zkratka</translation>
        </message>
        <message>
            <source>Description</source>
            <translation>Popis</translation>
        </message>
        <message>
            <source>One side's valve type has no such parameter; it cannot be chosen.</source>
            <translation>Typ ventilu jedné strany tento parametr nemá; nelze jej zvolit.</translation>
        </message>
        <message>
            <source>The valve type has this parameter, but the valve does not (a valve over CANopen without this object): not compared, not a difference; it cannot be chosen.</source>
            <translation>Typ ventilu tento parametr má, ventil však ne (ventil přes CANopen bez tohoto objektu): neporovnává se, není to rozdíl; nelze jej zvolit.</translation>
        </message>
    </context>
    <context>
        <name>CompareWorkflow</name>
        <message>
            <source>History: {0}</source>
            <translation>Historie: {0}</translation>
        </message>
        <message>
            <source>Document</source>
            <translation>Dokument</translation>
        </message>
        <message>
            <source>Valve {0}</source>
            <translation>Ventil {0}</translation>
        </message>
        <message>
            <source>Factory defaults</source>
            <translation>Tovární nastavení</translation>
        </message>
        <message>
            <source>Compare with file</source>
            <translation>Porovnat se souborem</translation>
        </message>
        <message>
            <source>Parameter files (*.prm);;All files (*)</source>
            <translation>Soubory parametrů (*.prm);;Všechny soubory (*)</translation>
        </message>
        <message>
            <source>{0} cannot be compared.</source>
            <translation>{0} nelze porovnat.</translation>
        </message>
        <message>
            <source>Values taken from {0}</source>
            <translation>Hodnoty převzaté z {0}</translation>
        </message>
        <message>
            <source>Compare with valve</source>
            <translation>Porovnat s ventilem</translation>
        </message>
        <message>
            <source>Go online with the valve first (Communication → Online mode).</source>
            <translation>Nejprve se připojte k ventilu (Komunikace → Režim online).</translation>
        </message>
        <message>
            <source>Values taken from the valve</source>
            <translation>Hodnoty převzaté z ventilu</translation>
        </message>
        <message>
            <source>Values chosen from the valve</source>
            <translation>Hodnoty zvolené z ventilu</translation>
        </message>
        <message>
            <source>Online: document and valve agree</source>
            <translation>Online: dokument a ventil se shodují</translation>
        </message>
        <message>
            <source>Parameters restored from the history</source>
            <translation>Parametry obnovené z historie</translation>
        </message>
        <message numerus="yes">
            <source>%n value(s) taken from the history</source>
            <translation>
                <numerusform>%n hodnota převzata z historie</numerusform>
                <numerusform>%n hodnoty převzaty z historie</numerusform>
                <numerusform>%n hodnot převzato z historie</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>ControlPanel</name>
        <message>
            <source>Recording</source>
            <translation>Záznam</translation>
        </message>
        <message>
            <source>Interval</source>
            <translation>Interval</translation>
        </message>
        <message>
            <source>Time window</source>
            <translation>Časové okno</translation>
        </message>
        <message>
            <source>Start</source>
            <translation>Start</translation>
        </message>
        <message>
            <source>Stop</source>
            <translation>Stop</translation>
        </message>
        <message>
            <source>Trigger</source>
            <translation>Spouštění</translation>
        </message>
        <message>
            <source>Roll (no trigger)</source>
            <translation>Průběžně (bez spouštění)</translation>
        </message>
        <message>
            <source>Auto</source>
            <translation>Auto</translation>
        </message>
        <message>
            <source>Normal</source>
            <translation>Normální</translation>
        </message>
        <message>
            <source>Single</source>
            <translation>Jednorázově</translation>
        </message>
        <message>
            <source>Rising edge</source>
            <translation>Náběžná hrana</translation>
        </message>
        <message>
            <source>Falling edge</source>
            <translation>Sestupná hrana</translation>
        </message>
        <message>
            <source>Pre-trigger</source>
            <translation>Předstih</translation>
        </message>
        <message>
            <source>Trigger level in the trigger channel's unit</source>
            <translation>Úroveň spouštění v jednotce spouštěcího kanálu</translation>
        </message>
        <message>
            <source>Resume</source>
            <translation>Pokračovat</translation>
        </message>
        <message>
            <source>Pause</source>
            <translation>Pozastavit</translation>
        </message>
        <message>
            <source>CSV of the visible window…</source>
            <translation>CSV viditelného okna…</translation>
        </message>
        <message>
            <source>CSV of the whole recording…</source>
            <translation>CSV celého záznamu…</translation>
        </message>
        <message>
            <source>Export</source>
            <translation>Export</translation>
        </message>
        <message>
            <source>Level</source>
            <translation>Úroveň</translation>
        </message>
        <message>
            <source>PNG image of the plot…</source>
            <translation>Graf jako obrázek PNG…</translation>
        </message>
        <message>
            <source>Trigger channel</source>
            <translation>Spouštěcí kanál</translation>
        </message>
    </context>
    <context>
        <name>ControllerDialog</name>
        <message>
            <source>Tuning and autotune…</source>
            <translation>Ladění a autotune…</translation>
        </message>
        <message>
            <source>No simulation available.</source>
            <translation>Simulace není k dispozici.</translation>
        </message>
        <message>
            <source>Simulation failed: %1</source>
            <translation>Simulace selhala: %1</translation>
        </message>
        <message>
            <source>setpoint</source>
            <translation>žádaná hodnota</translation>
        </message>
        <message>
            <source>applied values</source>
            <translation>použité hodnoty</translation>
        </message>
        <message>
            <source>actual value</source>
            <translation>skutečná hodnota</translation>
        </message>
        <message>
            <source>Time (ms)</source>
            <translation>Čas (ms)</translation>
        </message>
        <message>
            <source>Value (%)</source>
            <translation>Hodnota (%)</translation>
        </message>
        <message>
            <source>Simulated on the emulator's plant (no twin of this serial).</source>
            <translation>Simulováno na soustavě emulátoru (žádné dvojče tohoto výrobního čísla).</translation>
        </message>
        <message>
            <source>Simulated on the twin of serial {0} (fitted {1}).</source>
            <translation>Simulováno na dvojčeti výrobního čísla {0} (identifikováno {1}).</translation>
        </message>
    </context>
    <context>
        <name>CurrentDitherDialog</name>
        <message>
            <source>Nominal coil current CURNORM: %1 mA — no limit may exceed it.</source>
            <translation>Jmenovitý proud cívky CURNORM: %1 mA – žádná mez jej nesmí překročit.</translation>
        </message>
        <message>
            <source>Dither: ±%1 mA peak (DTAMP 100 % = %2 % of CURNORM).</source>
            <translation>Dynamické mazání: ±%1 mA špičkově (DTAMP 100 % = %2 % z CURNORM).</translation>
        </message>
        <message>
            <source>coil %1</source>
            <translation>cívka %1</translation>
        </message>
        <message>
            <source>limit %1</source>
            <translation>mez %1</translation>
        </message>
        <message>
            <source>Coil current (mA)</source>
            <translation>Proud cívky (mA)</translation>
        </message>
        <message>
            <source>Coil current (mA), coil B downwards</source>
            <translation>Proud cívky (mA), cívka B směrem dolů</translation>
        </message>
        <message>
            <source>Time (ms)</source>
            <translation>Čas (ms)</translation>
        </message>
    </context>
    <context>
        <name>CursorPanel</name>
        <message>
            <source>Cursors</source>
            <translation>Kurzory</translation>
        </message>
        <message>
            <source>Switch the cursors on to measure.</source>
            <translation>Pro měření zapněte kurzory.</translation>
        </message>
        <message>
            <source>Δt = {0}    1/Δt = {1}</source>
            <translation>Δt = {0}    1/Δt = {1}</translation>
        </message>
        <message>
            <source>Cursors A/B</source>
            <translation>Kurzory A/B</translation>
        </message>
    </context>
    <context>
        <name>CurveEditor</name>
        <message>
            <source>1:1</source>
            <translation>1:1</translation>
        </message>
        <message>
            <source>characteristic</source>
            <translation>charakteristika</translation>
        </message>
    </context>
    <context>
        <name>DcfExport</name>
        <message>
            <source>Export DCF</source>
            <translation>Export DCF</translation>
        </message>
        <message>
            <source>CANopen device configuration (*.dcf)</source>
            <translation>Konfigurace zařízení CANopen (*.dcf)</translation>
        </message>
        <message>
            <source>Cannot write “{0}”: {1}</source>
            <translation>„{0}“ nelze zapsat: {1}</translation>
        </message>
        <message>
            <source>DCF saved as {0} (node {1})</source>
            <translation>DCF uloženo jako {0} (uzel {1})</translation>
        </message>
    </context>
    <context>
        <name>DiagramBlock</name>
        <message>
            <source>spool position (LVDT)</source>
            <translation>poloha šoupátka (LVDT)</translation>
        </message>
        <message>
            <source>Setpoint input</source>
            <translation>Vstup žádané hodnoty</translation>
        </message>
        <message>
            <source>Threshold</source>
            <translation>Práh</translation>
        </message>
        <message>
            <source>Gain &amp; offset</source>
            <translation>Zesílení a posunutí</translation>
        </message>
        <message>
            <source>Linearization</source>
            <translation>Linearizace</translation>
        </message>
        <message>
            <source>Ramps</source>
            <translation>Rampy</translation>
        </message>
        <message>
            <source>Deviation gain &amp; offset</source>
            <translation>Odchylka: zesílení a posunutí</translation>
        </message>
        <message>
            <source>Process PIDT1</source>
            <translation>Procesní regulátor PIDT1</translation>
        </message>
        <message>
            <source>External sensor</source>
            <translation>Externí snímač</translation>
        </message>
        <message>
            <source>Sensor offset &amp; gain</source>
            <translation>Snímač: posunutí a zesílení</translation>
        </message>
        <message>
            <source>Sensor linearization</source>
            <translation>Linearizace snímače</translation>
        </message>
        <message>
            <source>Position PIDT1</source>
            <translation>Regulátor polohy PIDT1</translation>
        </message>
        <message>
            <source>Current limiter</source>
            <translation>Omezovač proudu</translation>
        </message>
        <message>
            <source>Dither</source>
            <translation>Dynamické mazání</translation>
        </message>
        <message>
            <source>Valve</source>
            <translation>Ventil</translation>
        </message>
        <message>
            <source>CANopen</source>
            <translation>CANopen</translation>
        </message>
        <message>
            <source>Supply</source>
            <translation>Napájení</translation>
        </message>
    </context>
    <context>
        <name>DiagramSummary</name>
        <message>
            <source>Polarity: %1</source>
            <translation>Polarita: %1</translation>
        </message>
        <message>
            <source>Threshold %1</source>
            <translation>Práh %1</translation>
        </message>
        <message>
            <source>Gain %1</source>
            <translation>Zesílení %1</translation>
        </message>
        <message>
            <source>Offset %1</source>
            <translation>Posunutí %1</translation>
        </message>
        <message>
            <source>9-point curve on</source>
            <translation>9bodová křivka zapnuta</translation>
        </message>
        <message>
            <source>off (1:1)</source>
            <translation>vypnuto (1:1)</translation>
        </message>
        <message>
            <source>Coil %1: %2</source>
            <translation>Cívka %1: %2</translation>
        </message>
        <message>
            <source>Amplitude %1</source>
            <translation>Amplituda %1</translation>
        </message>
        <message>
            <source>Frequency %1</source>
            <translation>Frekvence %1</translation>
        </message>
        <message>
            <source>coils A and B</source>
            <translation>cívky A a B</translation>
        </message>
        <message>
            <source>coil A only</source>
            <translation>pouze cívka A</translation>
        </message>
        <message>
            <source>coil B only</source>
            <translation>pouze cívka B</translation>
        </message>
        <message>
            <source>Voltage, temperature</source>
            <translation>Napětí, teplota</translation>
        </message>
        <message>
            <source>(live values)</source>
            <translation>(aktuální hodnoty)</translation>
        </message>
        <message>
            <source>CANopen off</source>
            <translation>CANopen vypnuto</translation>
        </message>
        <message>
            <source>analog setpoint</source>
            <translation>analogová žádaná hodnota</translation>
        </message>
        <message>
            <source>auto bit rate</source>
            <translation>rychlost auto</translation>
        </message>
        <message>
            <source>Node ID %1 · %2</source>
            <translation>Node ID %1 · %2</translation>
        </message>
        <message>
            <source>Rotary switches: interface %1, node ID %2 (read by the valve at power-up; before a valve was read, the delivery state).</source>
            <translation>Otočné přepínače: rozhraní %1, Node ID %2 (ventil je čte při zapnutí; dokud nebyl načten žádný ventil, stav při dodání).</translation>
        </message>
        <message>
            <source>Terminator %1</source>
            <translation>Terminátor %1</translation>
        </message>
    </context>
    <context>
        <name>DiagramView</name>
        <message>
            <source>Values measured by the valve; see the red measuring points.</source>
            <translation>Hodnoty měřené ventilem; viz červené měřicí body.</translation>
        </message>
        <message>
            <source>Click to edit: %1</source>
            <translation>Klepnutím upravíte: %1</translation>
        </message>
        <message>
            <source>(View → Access level)</source>
            <translation>(Náhled → Úroveň oprávnění)</translation>
        </message>
        <message>
            <source>Online, the valve type is that of the connected valve.</source>
            <translation>V režimu online je typ ventilu dán připojeným ventilem.</translation>
        </message>
        <message>
            <source>%1 — no live value now: the valve streams three measuring points at a time and the oscilloscope is recording others (over CANopen: the valve has no object for this point).</source>
            <translation>%1 – nyní bez živé hodnoty: ventil přenáší tři měřicí body najednou a osciloskop zaznamenává jiné (přes CANopen: ventil pro tento bod nemá objekt).</translation>
        </message>
        <message>
            <source>%1 — click to show it in the oscilloscope</source>
            <translation>%1 – klepnutím jej zobrazíte v osciloskopu</translation>
        </message>
        <message>
            <source>%1 — offline: measuring points show live values only with a valve online.</source>
            <translation>%1 – offline: měřicí body zobrazují aktuální hodnoty jen s ventilem v režimu online.</translation>
        </message>
        <message>
            <source>Zoom to fit</source>
            <translation>Přizpůsobit oknu</translation>
        </message>
        <message>
            <source>Zoom in</source>
            <translation>Přiblížit</translation>
        </message>
        <message>
            <source>Zoom out</source>
            <translation>Oddálit</translation>
        </message>
    </context>
    <context>
        <name>Edits</name>
        <message>
            <source>Valve selection {0}</source>
            <translation>Výběr ventilu {0}</translation>
        </message>
        <message>
            <source>{0}{1} rounded to {2}{1} (resolution {3}{1})</source>
            <translation>{0}{1} zaokrouhleno na {2}{1} (rozlišení {3}{1})</translation>
        </message>
        <message>
            <source>All ramps = {0}{1}</source>
            <translation>Všechny rampy = {0}{1}</translation>
        </message>
    </context>
    <context>
        <name>EdsExport</name>
        <message>
            <source>Export EDS</source>
            <translation>Export EDS</translation>
        </message>
        <message>
            <source>CANopen electronic data sheet (*.eds)</source>
            <translation>Elektronický datový list CANopen (*.eds)</translation>
        </message>
        <message>
            <source>Cannot write “{0}”: {1}</source>
            <translation>„{0}“ nelze zapsat: {1}</translation>
        </message>
        <message>
            <source>EDS saved as {0}</source>
            <translation>EDS uloženo jako {0}</translation>
        </message>
    </context>
    <context>
        <name>Emcy</name>
        <message>
            <source>Warning: electronics temperature above 70 °C</source>
            <translation>Varování: teplota elektroniky nad 70 °C</translation>
        </message>
        <message>
            <source>General error</source>
            <translation>Obecná chyba</translation>
        </message>
        <message>
            <source>Supply voltage out of range</source>
            <translation>Napájecí napětí mimo rozsah</translation>
        </message>
        <message>
            <source>Setpoint signal error (e.g. 4…20 mA wire break)</source>
            <translation>Chyba signálu žádané hodnoty (např. přerušení vodiče 4…20 mA)</translation>
        </message>
        <message>
            <source>Electronics temperature above 100 °C</source>
            <translation>Teplota elektroniky nad 100 °C</translation>
        </message>
        <message>
            <source>External sensor error</source>
            <translation>Chyba externího snímače</translation>
        </message>
        <message>
            <source>Solenoid A over-current or disconnected</source>
            <translation>Cívka A: nadproud nebo odpojení</translation>
        </message>
        <message>
            <source>Solenoid B over-current or disconnected</source>
            <translation>Cívka B: nadproud nebo odpojení</translation>
        </message>
        <message>
            <source>Internal position sensor error</source>
            <translation>Chyba interního snímače polohy</translation>
        </message>
        <message>
            <source>Unknown error</source>
            <translation>Neznámá chyba</translation>
        </message>
        <message>
            <source>ok</source>
            <translation>ok</translation>
        </message>
        <message>
            <source>CANopen communication error (heartbeat, SYNC or RPDO missing)</source>
            <translation>Chyba komunikace CANopen (chybí heartbeat, SYNC nebo RPDO)</translation>
        </message>
        <message>
            <source>CANopen RPDO too short: not processed</source>
            <translation>CANopen RPDO je příliš krátké: nezpracováno</translation>
        </message>
    </context>
    <context>
        <name>EmulatedValve</name>
        <message>
            <source>Coil A disconnected</source>
            <translation>Cívka A odpojena</translation>
        </message>
        <message>
            <source>Coil A short circuit (over-current)</source>
            <translation>Cívka A zkrat (nadproud)</translation>
        </message>
        <message>
            <source>Coil B disconnected</source>
            <translation>Cívka B odpojena</translation>
        </message>
        <message>
            <source>Coil B short circuit (over-current)</source>
            <translation>Cívka B zkrat (nadproud)</translation>
        </message>
        <message>
            <source>Setpoint wire break</source>
            <translation>Přerušený vodič žádané hodnoty</translation>
        </message>
        <message>
            <source>External sensor wire break</source>
            <translation>Přerušený vodič externího snímače</translation>
        </message>
        <message>
            <source>Spool position sensor (LVDT) wire break</source>
            <translation>Přerušený vodič snímače polohy šoupátka (LVDT)</translation>
        </message>
        <message>
            <source>Supply too low (17 V)</source>
            <translation>Napájení příliš nízké (17 V)</translation>
        </message>
        <message>
            <source>Supply too high (31 V)</source>
            <translation>Napájení příliš vysoké (31 V)</translation>
        </message>
        <message>
            <source>Over-temperature (105 °C)</source>
            <translation>Přehřátí (105 °C)</translation>
        </message>
    </context>
    <context>
        <name>EmulatedValveDialog</name>
        <message>
            <source>Emulated valve</source>
            <translation>Emulovaný ventil</translation>
        </message>
        <message>
            <source>Setpoint input [{0}]:</source>
            <translation>Vstup žádané hodnoty [{0}]:</translation>
        </message>
        <message>
            <source>External sensor input [{0}]:</source>
            <translation>Vstup externího snímače [{0}]:</translation>
        </message>
        <message>
            <source>Supply voltage [V]:</source>
            <translation>Napájecí napětí [V]:</translation>
        </message>
        <message>
            <source>Ambient temperature [°C]:</source>
            <translation>Okolní teplota [°C]:</translation>
        </message>
        <message>
            <source>Interface / bit-rate switch:</source>
            <translation>Přepínač rozhraní / přenosové rychlosti:</translation>
        </message>
        <message>
            <source>Node-ID switch:</source>
            <translation>Přepínač Node ID:</translation>
        </message>
        <message>
            <source>The valve reads its rotary switches at power-up only: restart it (Valve → Restart valve) for a new position to apply. The setpoint input counts only while the valve takes its setpoint from the analog input (no CANopen, no setpoint generator).</source>
            <translation>Ventil čte své otočné přepínače jen po zapnutí: restartujte ho (Ventil → Restart ventilu), aby platila nová poloha. Vstup žádané hodnoty platí jen tehdy, když ventil bere žádanou hodnotu z analogového vstupu (bez CANopen, bez generátoru žádané hodnoty).</translation>
        </message>
        <message>
            <source>node ID and bit rate by software (NODEID, BITRATE)</source>
            <translation>Node ID a přenosová rychlost softwarem (NODEID, BITRATE)</translation>
        </message>
        <message>
            <source>LSS: node ID from an LSS master, automatic bit rate</source>
            <translation>LSS: Node ID od LSS mastera, automatická přenosová rychlost</translation>
        </message>
        <message>
            <source>node {0}</source>
            <translation>uzel {0}</translation>
        </message>
    </context>
    <context>
        <name>EmulatedValveMenu</name>
        <message>
            <source>E&amp;mulated valve</source>
            <translation>E&amp;mulovaný ventil</translation>
        </message>
        <message>
            <source>&amp;Inputs and switches…</source>
            <translation>&amp;Vstupy a přepínače…</translation>
        </message>
        <message>
            <source>Setpoint and sensor signals, supply, temperature and rotary switches</source>
            <translation>Signály žádané hodnoty a snímače, napájení, teplota a otočné přepínače</translation>
        </message>
        <message>
            <source>&amp;Pull the USB cable</source>
            <translation>&amp;Vytáhnout kabel USB</translation>
        </message>
        <message>
            <source>The link drops as when a real cable is pulled; it stays out until plugged back</source>
            <translation>Spojení se přeruší jako při vytažení skutečného kabelu; kabel zůstane vytažený, dokud se znovu nezapojí</translation>
        </message>
        <message>
            <source>Plug the USB &amp;cable back in</source>
            <translation>Znovu zapojit &amp;kabel USB</translation>
        </message>
        <message>
            <source>The emulated valve is connected again; prm9tool finds it by itself</source>
            <translation>Emulovaný ventil je opět připojen; prm9tool jej najde sám</translation>
        </message>
        <message>
            <source>Inject this fault into the emulated valve, or repair it</source>
            <translation>Vyvolat tuto poruchu v emulovaném ventilu, nebo ji odstranit</translation>
        </message>
    </context>
    <context>
        <name>EmulatorDialog</name>
        <message>
            <source>Add emulated valve</source>
            <translation>Přidat emulovaný ventil</translation>
        </message>
        <message>
            <source>none: the emulator's plant</source>
            <translation>žádné: soustava emulátoru</translation>
        </message>
        <message>
            <source>A twin brings its own type key, serial number and parameter set.</source>
            <translation>Dvojče si přináší vlastní typový klíč, výrobní číslo a sadu parametrů.</translation>
        </message>
        <message>
            <source>Browse…</source>
            <translation>Procházet…</translation>
        </message>
        <message>
            <source>Serial number:</source>
            <translation>Výrobní číslo:</translation>
        </message>
        <message>
            <source>Twin from the history:</source>
            <translation>Dvojče z historie:</translation>
        </message>
        <message>
            <source>Twin file:</source>
            <translation>Soubor dvojčete:</translation>
        </message>
        <message>
            <source>none</source>
            <translation>žádné</translation>
        </message>
        <message>
            <source>fitted {0}: {1}</source>
            <translation>identifikováno {0}: {1}</translation>
        </message>
        <message>
            <source>{0} (cannot be used: {1})</source>
            <translation>{0} (nelze použít: {1})</translation>
        </message>
        <message>
            <source>Twin file</source>
            <translation>Soubor dvojčete</translation>
        </message>
        <message>
            <source>Twin files (*.toml)</source>
            <translation>Soubory dvojčat (*.toml)</translation>
        </message>
    </context>
    <context>
        <name>Errors</name>
        <message>
            <source>The valve could not be reached.</source>
            <translation>Ventil není dostupný.</translation>
        </message>
        <message>
            <source>The valve did not answer in time.</source>
            <translation>Ventil neodpověděl včas.</translation>
        </message>
        <message>
            <source>The valve answered something prm9tool does not understand.</source>
            <translation>Ventil odpověděl něco, čemu prm9tool nerozumí.</translation>
        </message>
        <message>
            <source>The connection to the valve is broken.</source>
            <translation>Spojení s ventilem je přerušeno.</translation>
        </message>
        <message>
            <source>The CAN adapter went bus-off: check the wiring, termination and bit rate.</source>
            <translation>CAN adaptér přešel do stavu bus-off: zkontrolujte kabeláž, zakončení sběrnice a přenosovou rychlost.</translation>
        </message>
        <message>
            <source>The emulated valve could not join the CAN bus; it works over USB without CAN.</source>
            <translation>Emulovaný ventil se nemohl připojit ke sběrnici CAN; pracuje přes USB bez CAN.</translation>
        </message>
        <message>
            <source>The CAN interface could not be opened.</source>
            <translation>Rozhraní CAN nelze otevřít.</translation>
        </message>
        <message>
            <source>The valve refused the access.</source>
            <translation>Ventil přístup odmítl.</translation>
        </message>
        <message>
            <source>The history database cannot be used.</source>
            <translation>Databázi historie nelze použít.</translation>
        </message>
        <message>
            <source>node {0} is NMT {1}: the valve takes RPDOs only when OPERATIONAL — start it first (Valve status → Commissioning: NMT start)</source>
            <translation>uzel {0} je ve stavu NMT {1}: ventil přijímá RPDO jen ve stavu OPERATIONAL — nejprve jej spusťte (Stav ventilu → Uvedení do provozu: NMT start)</translation>
        </message>
        <message>
            <source>node {0} is in {1}: the valve applies a setpoint from the bus only in DEVICE_MODE_ACTIVE — enable it first (Valve status → Commissioning: control word 08h→09h→0Bh→0Fh)</source>
            <translation>uzel {0} je ve stavu {1}: ventil přebírá žádanou hodnotu ze sběrnice jen v DEVICE_MODE_ACTIVE — nejprve jej uvolněte (Stav ventilu → Uvedení do provozu: řídicí slovo 08h→09h→0Bh→0Fh)</translation>
        </message>
        <message>
            <source>node {0}: RPDO1 is switched off (0x1400/1 = {1}, bit 31): clear bit 31 to drive the setpoint from prm9tool</source>
            <translation>uzel {0}: RPDO1 je vypnuto (0x1400/1 = {1}, bit 31): vynulujte bit 31, aby prm9tool mohl zadávat žádanou hodnotu</translation>
        </message>
        <message>
            <source>node {0}: RPDO1 is synchronous (0x1400/2 = {1}), so the setpoint would wait for a SYNC: set 0x1400/2 to 255 (the delivery state)</source>
            <translation>uzel {0}: RPDO1 je synchronní (0x1400/2 = {1}), žádaná hodnota by čekala na SYNC: nastavte 0x1400/2 na 255 (stav při dodání)</translation>
        </message>
        <message>
            <source>node {0}: RPDO1 maps {1}, not the setpoint 0x6300/0x6380</source>
            <translation>uzel {0}: RPDO1 mapuje {1}, ne žádanou hodnotu 0x6300/0x6380</translation>
        </message>
        <message>
            <source>The valve restarted at another address or bit rate: go online with it there.</source>
            <translation>Ventil se restartoval s jinou adresou nebo rychlostí: připojte se k němu tam.</translation>
        </message>
        <message>
            <source>The link could not keep the test's sample rate.</source>
            <translation>Spojení nedokázalo udržet vzorkovací frekvenci testu.</translation>
        </message>
        <message>
            <source>Node ID assignment (LSS) did not complete.</source>
            <translation>Přidělení Node ID (LSS) nebylo dokončeno.</translation>
        </message>
        <message>
            <source>The bit rate cannot be found without transmitting on this adapter.</source>
            <translation>S tímto adaptérem nelze přenosovou rychlost zjistit bez vysílání.</translation>
        </message>
        <message>
            <source>No bit rate gave valid frames.</source>
            <translation>Při žádné přenosové rychlosti nepřišly platné rámce.</translation>
        </message>
        <message>
            <source>The acceptance profile cannot be used.</source>
            <translation>Přejímací profil nelze použít.</translation>
        </message>
        <message>
            <source>the valve stays in {0}: error 0x{1} ({2}) is still present — remove its cause, then enable again (the control word 08h resets the fault once it is gone)</source>
            <translation>Ventil zůstává ve stavu {0}: chyba 0x{1} ({2}) stále trvá — odstraňte její příčinu a pak jej znovu povolte (řídicí slovo 08h resetuje poruchu, jakmile pomine)</translation>
        </message>
        <message>
            <source>the valve stays in {0} with no error present: it did not take the fault reset — write the control word 00h, then enable again</source>
            <translation>Ventil zůstává ve stavu {0}, ačkoli žádná chyba netrvá: reset poruchy nepřijal — zapište řídicí slovo 00h a pak jej znovu povolte</translation>
        </message>
        <message>
            <source>the valve is NMT stopped and takes no control word: send NMT start first</source>
            <translation>Ventil je ve stavu NMT zastaven a nepřijímá řídicí slovo: nejprve pošlete NMT start</translation>
        </message>
        <message>
            <source>the valve is still starting up (about 2 s after power-up): enable it then</source>
            <translation>Ventil se ještě spouští (asi 2 s po zapnutí): povolte jej potom</translation>
        </message>
        <message>
            <source>the valve is in NOT_READY after the control word 08h → 09h → 0Bh → 0Fh: it has not finished starting up (about 2 s after power-up) — wait until it has, then enable again; if it stays in NOT_READY, check its supply voltage (19.2 … 28 V)</source>
            <translation>Ventil je po řídicím slově 08h → 09h → 0Bh → 0Fh ve stavu NOT_READY: ještě nedokončil spuštění (asi 2 s po zapnutí) — počkejte, až se spustí, a pak jej znovu povolte; pokud zůstane ve stavu NOT_READY, zkontrolujte jeho napájecí napětí (19,2 … 28 V)</translation>
        </message>
        <message>
            <source>the valve is in {0} after the control word 08h → 09h → 0Bh → 0Fh, not DEVICE_MODE_ACTIVE</source>
            <translation>Ventil je po řídicím slově 08h → 09h → 0Bh → 0Fh ve stavu {0}, ne DEVICE_MODE_ACTIVE</translation>
        </message>
        <message>
            <source>the valve stays in DEVICE_MODE_ACTIVE after the control word 0Fh → 0Bh → 09h → 08h and still follows its setpoint — make the hydraulics safe, then look for another CANopen master enabling it or restart the valve</source>
            <translation>Ventil po řídicím slově 0Fh → 0Bh → 09h → 08h zůstává ve stavu DEVICE_MODE_ACTIVE a dál sleduje žádanou hodnotu – uveďte hydrauliku do bezpečného stavu, pak hledejte jiný CANopen master, který ho uvolňuje, nebo ventil restartujte</translation>
        </message>
        <message>
            <source>The valve has no birth certificate in the history.</source>
            <translation>Ventil nemá v historii rodný list.</translation>
        </message>
        <message>
            <source>The valve stopped sending its measuring points.</source>
            <translation>Ventil přestal posílat své měřicí body.</translation>
        </message>
    </context>
    <context>
        <name>EventTableModel</name>
        <message>
            <source>Time (s)</source>
            <translation>Čas (s)</translation>
        </message>
        <message>
            <source>Node</source>
            <translation>Uzel</translation>
        </message>
        <message>
            <source>Kind</source>
            <translation>Druh</translation>
        </message>
        <message>
            <source>What</source>
            <translation>Co</translation>
        </message>
        <message>
            <source>Frames</source>
            <translation>Rámce</translation>
        </message>
    </context>
    <context>
        <name>FileWorkflow</name>
        <message>
            <source>untitled</source>
            <translation>nepojmenovaná</translation>
        </message>
        <message>
            <source>Unsaved changes</source>
            <translation>Neuložené změny</translation>
        </message>
        <message>
            <source>The parameters in “{0}” have been changed. Save the changes?</source>
            <translation>Parametry v „{0}“ byly změněny. Uložit změny?</translation>
        </message>
        <message>
            <source>New parameter set for {0}</source>
            <translation>Nový záznam parametrů pro {0}</translation>
        </message>
        <message>
            <source>Open parameter file</source>
            <translation>Otevřít záznam parametrů</translation>
        </message>
        <message>
            <source>Parameter files (*.prm);;All files (*)</source>
            <translation>Záznamy parametrů (*.prm);;Všechny soubory (*)</translation>
        </message>
        <message>
            <source>File not found</source>
            <translation>Soubor nenalezen</translation>
        </message>
        <message>
            <source>“{0}” no longer exists; it was removed from the list.</source>
            <translation>„{0}“ již neexistuje; byl odstraněn ze seznamu.</translation>
        </message>
        <message>
            <source>Opening {0} cancelled</source>
            <translation>Otevírání {0} zrušeno</translation>
        </message>
        <message>
            <source>Backup copy saved as {0}; {1} stays the open document</source>
            <translation>Záložní kopie uložena jako {0}; otevřený zůstává dokument {1}</translation>
        </message>
        <message>
            <source>Still reading {0}</source>
            <translation>{0} se ještě načítá</translation>
        </message>
        <message>
            <source>Cannot open “{0}”</source>
            <translation>„{0}“ nelze otevřít</translation>
        </message>
        <message>
            <source>Opened {0}</source>
            <translation>Otevřeno: {0}</translation>
        </message>
        <message>
            <source>Opened with warnings</source>
            <translation>Otevřeno s varováními</translation>
        </message>
        <message numerus="yes">
            <source>“{0}” was opened; %n warning(s) were found.</source>
            <translation>
                <numerusform>„{0}“ byl otevřen; nalezeno %n varování.</numerusform>
                <numerusform>„{0}“ byl otevřen; nalezena %n varování.</numerusform>
                <numerusform>„{0}“ byl otevřen; nalezeno %n varování.</numerusform>
            </translation>
        </message>
        <message>
            <source>Reading “{0}”…</source>
            <translation>Načítá se „{0}“…</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>Zrušit</translation>
        </message>
        <message>
            <source>Save parameter file</source>
            <translation>Uložit záznam parametrů</translation>
        </message>
        <message>
            <source>Parameter files (*.prm)</source>
            <translation>Záznamy parametrů (*.prm)</translation>
        </message>
        <message>
            <source>Cannot save “{0}”</source>
            <translation>„{0}“ nelze uložit</translation>
        </message>
        <message numerus="yes">
            <source>(marked: %n rule(s) broken)</source>
            <translation>
                <numerusform>(označeno: porušeno %n pravidlo)</numerusform>
                <numerusform>(označeno: porušena %n pravidla)</numerusform>
                <numerusform>(označeno: porušeno %n pravidel)</numerusform>
            </translation>
        </message>
        <message>
            <source>Save backup copy</source>
            <translation>Uložit záložní kopii</translation>
        </message>
        <message>
            <source>Saved {0}</source>
            <translation>Uloženo: {0}</translation>
        </message>
        <message numerus="yes">
            <source>%n more problem(s) in the details.</source>
            <translation>
                <numerusform>Další %n problém v podrobnostech.</numerusform>
                <numerusform>Další %n problémy v podrobnostech.</numerusform>
                <numerusform>Dalších %n problémů v podrobnostech.</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>… and %n more problem(s).</source>
            <translation>
                <numerusform>… a %n další problém.</numerusform>
                <numerusform>… a %n další problémy.</numerusform>
                <numerusform>… a dalších %n problémů.</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>FlowPage</name>
        <message>
            <source>process setpoint steps %1 → %2 → %1 % with the process controller proportional only, %3 s each</source>
            <translation>skoky žádané procesní veličiny %1 → %2 → %1 % s čistě proporcionálním procesním regulátorem, každý %3 s</translation>
        </message>
        <message>
            <source>Flow characteristic</source>
            <translation>Průtoková charakteristika</translation>
        </message>
        <message>
            <source>spool opening [%]</source>
            <translation>otevření šoupátka [%]</translation>
        </message>
        <message>
            <source>actuator velocity [%/s]</source>
            <translation>rychlost pohonu [%/s]</translation>
        </message>
        <message>
            <source>measured</source>
            <translation>změřeno</translation>
        </message>
        <message>
            <source>with the proposed offsets (preview)</source>
            <translation>s navrženým posunutím nuly (náhled)</translation>
        </message>
        <message>
            <source>Flow gain %1 %/s per % of opening, dead band %2 … %3 % (width %4 %). Proposed offsets on the control deviation (process Kp %5): %6.</source>
            <translation>Průtokové zesílení %1 %/s na % otevření, pásmo necitlivosti %2 … %3 % (šířka %4 %). Navržené posunutí nuly regulační odchylky (procesní Kp %5): %6.</translation>
        </message>
        <message>
            <source>Offsets from the flow characteristic</source>
            <translation>Posunutí nuly z průtokové charakteristiky</translation>
        </message>
        <message>
            <source>Step around the operating point:</source>
            <translation>Skok kolem pracovního bodu:</translation>
        </message>
        <message>
            <source>Operating point:</source>
            <translation>Pracovní bod:</translation>
        </message>
        <message>
            <source>Duration of each step:</source>
            <translation>Trvání každého skoku:</translation>
        </message>
        <message>
            <source>Measure the flow characteristic</source>
            <translation>Změřit průtokovou charakteristiku</translation>
        </message>
        <message>
            <source>Apply the proposed offsets</source>
            <translation>Použít navržené posunutí nuly</translation>
        </message>
    </context>
    <context>
        <name>GeneratorPanel</name>
        <message>
            <source>Step</source>
            <translation>Skok</translation>
        </message>
        <message>
            <source>Square</source>
            <translation>Obdélník</translation>
        </message>
        <message>
            <source>Sine</source>
            <translation>Sinus</translation>
        </message>
        <message>
            <source>Waveform</source>
            <translation>Průběh</translation>
        </message>
        <message>
            <source>Period</source>
            <translation>Perioda</translation>
        </message>
        <message>
            <source>Amplitude</source>
            <translation>Amplituda</translation>
        </message>
        <message>
            <source>Offset</source>
            <translation>Posunutí</translation>
        </message>
        <message>
            <source>Step and square: height of the step above the offset. Sine: peak value. In % of the setpoint range.</source>
            <translation>Skok a obdélník: výška skoku nad posunutím. Sinus: amplituda. V % rozsahu žádané hodnoty.</translation>
        </message>
        <message>
            <source>Stop generator</source>
            <translation>Zastavit generátor</translation>
        </message>
        <message>
            <source>Start generator</source>
            <translation>Spustit generátor</translation>
        </message>
        <message>
            <source>Generator</source>
            <translation>Generátor</translation>
        </message>
        <message>
            <source>Setpoint generator: drives the valve's setpoint for tuning (manual §8.7.2)</source>
            <translation>Generátor žádané hodnoty: zadává žádanou hodnotu ventilu pro ladění regulátorů (návod §8.7.2)</translation>
        </message>
    </context>
    <context>
        <name>GeneratorSettings</name>
        <message>
            <source>The generator period must be longer than 0 s.</source>
            <translation>Perioda generátoru musí být delší než 0 s.</translation>
        </message>
        <message>
            <source>The waveform reaches {0} … {1} %; the setpoint must stay within {2} … {3} %.</source>
            <translation>Průběh dosahuje {0} … {1} %; žádaná hodnota musí zůstat v rozsahu {2} … {3} %.</translation>
        </message>
    </context>
    <context>
        <name>GeneratorStart</name>
        <message>
            <source>Setpoint generator</source>
            <translation>Generátor žádané hodnoty</translation>
        </message>
        <message>
            <source>The generator will drive the valve's setpoint and the valve will move.
Make sure the machine is safe to move. Start the generator?</source>
            <translation>Generátor bude řídit žádanou hodnotu ventilu a ventil se bude pohybovat.
Ujistěte se, že pohyb stroje je bezpečný. Spustit generátor?</translation>
        </message>
        <message>
            <source>The valve does not follow its setpoint: {0}

Enable it now (NMT start, control word 08h → 09h → 0Bh → 0Fh)?</source>
            <translation>Ventil nesleduje svou žádanou hodnotu: {0}

Uvolnit ho nyní (NMT start, řídicí slovo 08h → 09h → 0Bh → 0Fh)?</translation>
        </message>
    </context>
    <context>
        <name>Help</name>
        <message>
            <source>Home page</source>
            <translation>Domovská stránka</translation>
        </message>
        <message>
            <source>No web browser could be started. The home page is {0}</source>
            <translation>Nepodařilo se spustit webový prohlížeč. Domovská stránka je {0}</translation>
        </message>
        <message>
            <source>unknown</source>
            <translation>neznámé</translation>
        </message>
        <message>
            <source>{0} (single executable)</source>
            <translation>{0} (samostatný spustitelný soubor)</translation>
        </message>
        <message>
            <source>commit</source>
            <translation>Revize</translation>
        </message>
        <message>
            <source>built</source>
            <translation>Sestaveno</translation>
        </message>
    </context>
    <context>
        <name>HelpWindow</name>
        <message>
            <source>prm9tool help</source>
            <translation>prm9tool – nápověda</translation>
        </message>
    </context>
    <context>
        <name>HidConfigurationDialog</name>
        <message>
            <source>HID configuration</source>
            <translation>Konfigurace HID</translation>
        </message>
        <message>
            <source>Valves connected to this computer and emulated valves. Choose the one to communicate with.</source>
            <translation>Ventily připojené k tomuto počítači a emulované ventily. Zvolte ventil pro komunikaci.</translation>
        </message>
        <message>
            <source>Connection</source>
            <translation>Připojení</translation>
        </message>
        <message>
            <source>Type key</source>
            <translation>Typový klíč</translation>
        </message>
        <message>
            <source>Serial number</source>
            <translation>Výrobní číslo</translation>
        </message>
        <message>
            <source>Firmware</source>
            <translation>Firmware</translation>
        </message>
        <message>
            <source>Description</source>
            <translation>Popis</translation>
        </message>
        <message>
            <source>Add emulated valve…</source>
            <translation>Přidat emulovaný ventil…</translation>
        </message>
        <message>
            <source>Remove emulated valve</source>
            <translation>Odebrat emulovaný ventil</translation>
        </message>
        <message>
            <source>Refresh</source>
            <translation>Obnovit</translation>
        </message>
        <message>
            <source>Looking for valves…</source>
            <translation>Hledání ventilů…</translation>
        </message>
        <message>
            <source>Listing the valves failed: {0}</source>
            <translation>Výpis ventilů selhal: {0}</translation>
        </message>
        <message>
            <source>emulated {0}, serial {1}</source>
            <translation>emulovaný ventil {0}, výrobní číslo {1}</translation>
        </message>
        <message>
            <source>cannot be used (remove it): {0}</source>
            <translation>nelze použít (odeberte jej): {0}</translation>
        </message>
        <message>
            <source>Emulated valve</source>
            <translation>Emulovaný ventil</translation>
        </message>
        <message>
            <source>USB</source>
            <translation>USB</translation>
        </message>
    </context>
    <context>
        <name>HistoryPolicy</name>
        <message>
            <source>Upload refused</source>
            <translation>Načtení do ventilu odmítnuto</translation>
        </message>
        <message>
            <source>The history database cannot record this upload, and the setting says to refuse uploads then. Nothing was written to the valve.</source>
            <translation>Databáze historie nemůže toto načtení zaznamenat a nastavení v takovém případě načtení odmítá. Do ventilu nebylo nic zapsáno.</translation>
        </message>
        <message>
            <source>History database unavailable</source>
            <translation>Databáze historie není dostupná</translation>
        </message>
        <message>
            <source>The history database cannot record this upload. Upload anyway and keep the record on this computer until the database is back?

Yes uploads and queues the record; No uploads nothing.</source>
            <translation>Databáze historie nemůže toto načtení zaznamenat. Přesto načíst do ventilu a záznam uchovat v tomto počítači, dokud nebude databáze opět dostupná?

Ano načte a záznam zařadí do fronty; Ne nenačte nic.</translation>
        </message>
    </context>
    <context>
        <name>HistorySettingsDialog</name>
        <message>
            <source>History database</source>
            <translation>Databáze historie</translation>
        </message>
        <message>
            <source>ask before uploading</source>
            <translation>zeptat se před načtením do ventilu</translation>
        </message>
        <message>
            <source>refuse the upload (production line)</source>
            <translation>odmítnout načtení do ventilu (výrobní linka)</translation>
        </message>
        <message>
            <source>upload and keep the record here until the database is back</source>
            <translation>načíst do ventilu a záznam uchovat zde, dokud nebude databáze opět dostupná</translation>
        </message>
        <message>
            <source>Empty: SQLite on this computer. A line of stations: postgresql+psycopg://user:password@server/database</source>
            <translation>Prázdné: SQLite v tomto počítači. Linka s více stanicemi: postgresql+psycopg://uživatel:heslo@server/databáze</translation>
        </message>
        <message>
            <source>Database:</source>
            <translation>Databáze:</translation>
        </message>
        <message>
            <source>When it cannot be reached:</source>
            <translation>Když není dostupná:</translation>
        </message>
    </context>
    <context>
        <name>HistoryTableModel</name>
        <message>
            <source>No.</source>
            <translation>Č.</translation>
        </message>
        <message>
            <source>Time (UTC)</source>
            <translation>Čas (UTC)</translation>
        </message>
        <message>
            <source>Operation</source>
            <translation>Operace</translation>
        </message>
        <message>
            <source>Outcome</source>
            <translation>Výsledek</translation>
        </message>
        <message>
            <source>Type key</source>
            <translation>Typový klíč</translation>
        </message>
        <message>
            <source>What was done</source>
            <translation>Co bylo provedeno</translation>
        </message>
        <message>
            <source>Firmware</source>
            <translation>Firmware</translation>
        </message>
        <message>
            <source>User, station, link</source>
            <translation>Uživatel, stanice, připojení</translation>
        </message>
        <message>
            <source>ok</source>
            <translation>ok</translation>
        </message>
        <message>
            <source>passed</source>
            <translation>vyhověl</translation>
        </message>
        <message>
            <source>failed</source>
            <translation>nevyhověl</translation>
        </message>
        <message>
            <source>verification-failed</source>
            <translation>ověření selhalo</translation>
        </message>
        <message>
            <source>store-failed</source>
            <translation>uložení selhalo</translation>
        </message>
        <message>
            <source>communication-error</source>
            <translation>chyba komunikace</translation>
        </message>
        <message>
            <source>type-mismatch</source>
            <translation>jiný typ ventilu</translation>
        </message>
        <message>
            <source>error</source>
            <translation>chyba</translation>
        </message>
        <message>
            <source>dry-run</source>
            <translation>zkušební běh</translation>
        </message>
        <message>
            <source>downloaded</source>
            <translation>načteno z ventilu</translation>
        </message>
        <message>
            <source>proposed</source>
            <translation>návrh</translation>
        </message>
        <message>
            <source>targets-missed</source>
            <translation>cíle nesplněny</translation>
        </message>
        <message>
            <source>explained</source>
            <translation>vysvětleno</translation>
        </message>
        <message>
            <source>not-explained</source>
            <translation>nevysvětleno</translation>
        </message>
        <message>
            <source>no-drift</source>
            <translation>bez driftu</translation>
        </message>
        <message>
            <source>drifted</source>
            <translation>zjištěn drift</translation>
        </message>
        <message>
            <source>backup</source>
            <translation>záloha</translation>
        </message>
        <message>
            <source>write</source>
            <translation>zápis</translation>
        </message>
        <message>
            <source>verify</source>
            <translation>ověření</translation>
        </message>
        <message>
            <source>store</source>
            <translation>uložení</translation>
        </message>
        <message>
            <source>download</source>
            <translation>stažení z ventilu</translation>
        </message>
        <message>
            <source>upload</source>
            <translation>načtení do ventilu</translation>
        </message>
        <message>
            <source>batch-upload</source>
            <translation>načtení do ventilu (--batch)</translation>
        </message>
        <message>
            <source>online-edits</source>
            <translation>změny online</translation>
        </message>
        <message>
            <source>restore-factory</source>
            <translation>tovární nastavení</translation>
        </message>
        <message>
            <source>characterization</source>
            <translation>výstupní zkouška</translation>
        </message>
        <message>
            <source>compare-apply</source>
            <translation>převzato z porovnání</translation>
        </message>
        <message>
            <source>history-restore</source>
            <translation>obnoveno z historie</translation>
        </message>
        <message>
            <source>tuning-accepted</source>
            <translation>ladění převzato</translation>
        </message>
        <message>
            <source>restart-verify</source>
            <translation>ověření restartem</translation>
        </message>
        <message>
            <source>restart</source>
            <translation>restart</translation>
        </message>
        <message>
            <source>autotune</source>
            <translation>autotune</translation>
        </message>
        <message>
            <source>frequency-response</source>
            <translation>frekvenční charakteristika</translation>
        </message>
        <message>
            <source>report-saved</source>
            <translation>protokol uložen</translation>
        </message>
        <message>
            <source>twin</source>
            <translation>dvojče</translation>
        </message>
        <message>
            <source>signature</source>
            <translation>porovnání s rodným listem</translation>
        </message>
        <message>
            <source>Marked {0}: records of another valve type than {1} under this serial number — another valve (emulated valves of two runs of the program may share a serial number); compare or restore them only knowingly.</source>
            <translation>Označeno {0}: záznamy jiného typu ventilu než {1} pod tímto výrobním číslem — jiný ventil (emulované ventily dvou běhů programu mohou mít stejné výrobní číslo); porovnávejte nebo obnovujte je jen vědomě.</translation>
        </message>
        <message numerus="yes">
            <source>%n more</source>
            <translation>
                <numerusform>%n další</numerusform>
                <numerusform>%n další</numerusform>
                <numerusform>%n dalších</numerusform>
            </translation>
        </message>
        <message>
            <source>position loop</source>
            <translation>regulační smyčka polohy</translation>
        </message>
        <message>
            <source>process loop</source>
            <translation>regulační smyčka procesní veličiny</translation>
        </message>
        <message>
            <source>profile {0}</source>
            <translation>profil {0}</translation>
        </message>
        <message>
            <source>failed: {0}</source>
            <translation>nevyhovělo: {0}</translation>
        </message>
        <message>
            <source>PDF {0}</source>
            <translation>PDF {0}</translation>
        </message>
        <message>
            <source>proposed {0}</source>
            <translation>navrženo {0}</translation>
        </message>
        <message>
            <source>misses the targets</source>
            <translation>nesplňuje cíle</translation>
        </message>
        <message>
            <source>not found</source>
            <translation>nenalezeno</translation>
        </message>
        <message>
            <source>Read from the valve</source>
            <translation>Načteno z ventilu</translation>
        </message>
        <message>
            <source>Written, verified and stored</source>
            <translation>Zapsáno, ověřeno a uloženo</translation>
        </message>
        <message>
            <source>Written by --batch</source>
            <translation>Zapsáno pomocí --batch</translation>
        </message>
        <message>
            <source>Stored (Valve → Store in valve)</source>
            <translation>Uloženo (Ventil → Uložit do paměti ventilu)</translation>
        </message>
        <message>
            <source>Values changed online, stored</source>
            <translation>Hodnoty změněné online uloženy</translation>
        </message>
        <message>
            <source>Backup of the valve's values</source>
            <translation>Záloha hodnot ventilu</translation>
        </message>
        <message>
            <source>Factory values restored</source>
            <translation>Obnoveno tovární nastavení</translation>
        </message>
        <message>
            <source>Test report</source>
            <translation>Zkušební protokol</translation>
        </message>
        <message>
            <source>Values from a compared file, written online</source>
            <translation>Hodnoty z porovnávaného souboru, zapsány online</translation>
        </message>
        <message>
            <source>Values from the history, written online</source>
            <translation>Hodnoty z historie, zapsány online</translation>
        </message>
        <message>
            <source>Tuning accepted, written online</source>
            <translation>Nastavení regulace převzato, zapsáno online</translation>
        </message>
        <message>
            <source>Restarted and read back (Valve → Verify by restart…)</source>
            <translation>Restartováno a zpětně načteno (Ventil → Ověřit restartem…)</translation>
        </message>
        <message>
            <source>Restarted (Valve → Restart valve)</source>
            <translation>Restartováno (Ventil → Restart ventilu)</translation>
        </message>
        <message>
            <source>Autotune run</source>
            <translation>Běh Autotune</translation>
        </message>
        <message>
            <source>Frequency response measured</source>
            <translation>Frekvenční charakteristika změřena</translation>
        </message>
        <message>
            <source>Test report saved</source>
            <translation>Zkušební protokol uložen</translation>
        </message>
        <message>
            <source>Twin fitted (--fit-twin)</source>
            <translation>Digitální dvojče určeno (--fit-twin)</translation>
        </message>
        <message>
            <source>Compared with the birth certificate (--signature)</source>
            <translation>Porovnáno s rodným listem (--signature)</translation>
        </message>
        <message>
            <source>stored with 0x1010</source>
            <translation>uloženo pomocí 0x1010</translation>
        </message>
        <message>
            <source>kept by the valve as written (it has no store command)</source>
            <translation>ventil si hodnoty ponechal tak, jak byly zapsány (nemá příkaz k uložení)</translation>
        </message>
        <message>
            <source>verified after a restart</source>
            <translation>ověřeno po restartu</translation>
        </message>
        <message>
            <source>going online</source>
            <translation>při přechodu do režimu online</translation>
        </message>
        <message>
            <source>Valve → Download</source>
            <translation>Ventil → Stažení z ventilu</translation>
        </message>
        <message>
            <source>Compare with valve</source>
            <translation>Porovnat s ventilem</translation>
        </message>
        <message>
            <source>Valve → Upload</source>
            <translation>Ventil → Načtení do ventilu</translation>
        </message>
        <message>
            <source>chosen in the compare view</source>
            <translation>zvoleno v porovnání</translation>
        </message>
        <message>
            <source>chosen per parameter going online</source>
            <translation>zvoleno po parametrech při přechodu do režimu online</translation>
        </message>
        <message>
            <source>a history record restored</source>
            <translation>obnoven záznam z historie</translation>
        </message>
    </context>
    <context>
        <name>HistoryWindow</name>
        <message>
            <source>History</source>
            <translation>Historie</translation>
        </message>
        <message>
            <source>serial number</source>
            <translation>výrobní číslo</translation>
        </message>
        <message>
            <source>Show</source>
            <translation>Zobrazit</translation>
        </message>
        <message>
            <source>Valve serial number:</source>
            <translation>Výrobní číslo ventilu:</translation>
        </message>
        <message>
            <source>Compare the two selected records</source>
            <translation>Porovnat dva vybrané záznamy</translation>
        </message>
        <message>
            <source>Restore into the document</source>
            <translation>Obnovit do dokumentu</translation>
        </message>
        <message>
            <source>Restore to the valve</source>
            <translation>Obnovit do ventilu</translation>
        </message>
        <message>
            <source>Export…</source>
            <translation>Exportovat…</translation>
        </message>
        <message>
            <source>Database…</source>
            <translation>Databáze…</translation>
        </message>
        <message>
            <source>Type a valve's serial number.</source>
            <translation>Zadejte výrobní číslo ventilu.</translation>
        </message>
        <message>
            <source>Reading the history…</source>
            <translation>Čtení historie…</translation>
        </message>
        <message numerus="yes">
            <source>%n record(s) in {0}</source>
            <translation>
                <numerusform>%n záznam v {0}</numerusform>
                <numerusform>%n záznamy v {0}</numerusform>
                <numerusform>%n záznamů v {0}</numerusform>
            </translation>
        </message>
        <message>
            <source>This record holds no parameter set (the operation did not change the valve's stored parameters).</source>
            <translation>Tento záznam neobsahuje sadu parametrů (operace nezměnila uložené parametry ventilu).</translation>
        </message>
        <message>
            <source>No. {0}, {1}</source>
            <translation>Č. {0}, {1}</translation>
        </message>
        <message>
            <source>Go online with valve {0} first: a record is restored only into the valve it was recorded from.</source>
            <translation>Nejprve se připojte k ventilu {0}: záznam se obnovuje jen do ventilu, ze kterého pochází.</translation>
        </message>
        <message>
            <source>Export record</source>
            <translation>Exportovat záznam</translation>
        </message>
        <message>
            <source>Parameter files (*.prm);;CSV tables (*.csv)</source>
            <translation>Soubory parametrů (*.prm);;Tabulky CSV (*.csv)</translation>
        </message>
        <message>
            <source>The record was not exported.</source>
            <translation>Záznam nebyl exportován.</translation>
        </message>
    </context>
    <context>
        <name>LinearizationDialog</name>
        <message>
            <source>Input X (%)</source>
            <translation>Vstup X (%)</translation>
        </message>
        <message>
            <source>Output Y (%)</source>
            <translation>Výstup Y (%)</translation>
        </message>
        <message>
            <source>Reset to a straight line</source>
            <translation>Obnovit přímku</translation>
        </message>
        <message>
            <source>Input (%)</source>
            <translation>Vstup (%)</translation>
        </message>
        <message>
            <source>Output (%)</source>
            <translation>Výstup (%)</translation>
        </message>
        <message>
            <source>Linearization point %1</source>
            <translation>Bod linearizace %1</translation>
        </message>
        <message>
            <source>Linearization reset to a straight line</source>
            <translation>Linearizace obnovena na přímku</translation>
        </message>
    </context>
    <context>
        <name>LinkGuard</name>
        <message>
            <source>The connection will move</source>
            <translation>Spojení se změní</translation>
        </message>
        <message>
            <source>The node-ID switch is at position {0}: the switches decide node ID and bit rate (manual table 7-17), so this change does not move the valve; it stays at node {1}.</source>
            <translation>Přepínač Node ID je v poloze {0}: Node ID a přenosovou rychlost určují přepínače (návod, tabulka 7-17), tato změna tedy ventil nepřesune; zůstává uzlem {1}.</translation>
        </message>
        <message>
            <source>The node-ID switch is at position 1 (LSS): an LSS master sets node ID and bit rate (manual table 7-17; Communication → CAN bus). NODEID and BITRATE apply at position 0 only, so this change does not move the valve.</source>
            <translation>Přepínač Node ID je v poloze 1 (LSS): Node ID a přenosovou rychlost nastavuje LSS master (návod, tabulka 7-17; Komunikace → CAN sběrnice). NODEID a BITRATE platí jen v poloze 0, tato změna tedy ventil nepřesune.</translation>
        </message>
        <message>
            <source>After the valve's next power-up or restart it answers at node {0}, {1}. Store the change and restart the valve from prm9tool (Valve → Restart valve): prm9tool then finds it there again — where it cannot change the adapter's bit rate itself (SocketCAN), it says how. After a power-up, find it under Communication → CAN bus (node {0}, bit rate {1}).</source>
            <translation>Po příštím zapnutí nebo restartu ventil odpovídá jako uzel {0}, {1}. Uložte změnu a restartujte ventil z prm9tool (Ventil → Restart ventilu): prm9tool ho tam pak znovu najde — kde rychlost adaptéru sám změnit nemůže (SocketCAN), řekne jak. Po zapnutí ho najděte v Komunikace → Sběrnice CAN (uzel {0}, rychlost {1}).</translation>
        </message>
    </context>
    <context>
        <name>LssPanel</name>
        <message>
            <source>Devices without a node ID (node-ID switch at 1: LSS)</source>
            <translation>Zařízení bez Node ID (přepínač Node ID v poloze 1: LSS)</translation>
        </message>
        <message>
            <source>Serial</source>
            <translation>Sériové číslo</translation>
        </message>
        <message>
            <source>Device</source>
            <translation>Zařízení</translation>
        </message>
        <message>
            <source>Vendor ID</source>
            <translation>Vendor ID</translation>
        </message>
        <message>
            <source>Product code</source>
            <translation>Produktový klíč</translation>
        </message>
        <message>
            <source>Revision</source>
            <translation>Revize</translation>
        </message>
        <message>
            <source>Look for devices without a node ID</source>
            <translation>Hledat zařízení bez Node ID</translation>
        </message>
        <message>
            <source>Assign node ID…</source>
            <translation>Přidělit Node ID…</translation>
        </message>
        <message>
            <source>Assign node IDs to all…</source>
            <translation>Přidělit Node ID všem…</translation>
        </message>
        <message>
            <source>Looking for devices without a node ID (LSS Fastscan)…</source>
            <translation>Hledají se zařízení bez Node ID (LSS Fastscan)…</translation>
        </message>
        <message>
            <source>PRM9</source>
            <translation>PRM9</translation>
        </message>
        <message>
            <source>not a PRM9</source>
            <translation>není PRM9</translation>
        </message>
        <message numerus="yes">
            <source>%n device(s) without a node ID.</source>
            <translation>
                <numerusform>%n zařízení bez Node ID.</numerusform>
                <numerusform>%n zařízení bez Node ID.</numerusform>
                <numerusform>%n zařízení bez Node ID.</numerusform>
            </translation>
        </message>
        <message>
            <source>No device without a node ID answered: every device has one, or none is at node-ID switch 1, or the bus runs at another bit rate.</source>
            <translation>Neodpovědělo žádné zařízení bez Node ID: každé zařízení ho má, žádné nemá přepínač Node ID v poloze 1, nebo sběrnice běží jinou přenosovou rychlostí.</translation>
        </message>
        <message>
            <source>Assign node ID</source>
            <translation>Přidělit Node ID</translation>
        </message>
        <message>
            <source>Node ID for serial {0} (1…127; stored in the valve, used from now on and after every power-up):</source>
            <translation>Node ID pro sériové číslo {0} (1…127; uloží se do ventilu, platí ihned i po každém zapnutí):</translation>
        </message>
        <message>
            <source>Node ID {0} is taken: a node answers there. Choose another one.</source>
            <translation>Node ID {0} je obsazené: na něm odpovídá uzel. Zvolte jiné.</translation>
        </message>
        <message>
            <source>Giving serial {0} node ID {1} and storing it…</source>
            <translation>Sériové číslo {0} dostává Node ID {1} a ukládá ho…</translation>
        </message>
        <message>
            <source>Assign node IDs to all</source>
            <translation>Přidělit Node ID všem</translation>
        </message>
        <message>
            <source>First node ID: the {0} valves get consecutive free node IDs from it, in the order of their serial numbers (stored in each valve):</source>
            <translation>První Node ID: {0} ventilů dostane od něj po sobě jdoucí volná Node ID v pořadí sériových čísel (uloží se do každého ventilu):</translation>
        </message>
        <message>
            <source>From node ID {0} on there are only {1} free node IDs for {2} valves.</source>
            <translation>Od Node ID {0} je volných jen {1} Node ID pro {2} ventilů.</translation>
        </message>
        <message>
            <source>Giving node IDs: {0}…</source>
            <translation>Přidělují se Node ID: {0}…</translation>
        </message>
        <message>
            <source>Given and stored: {0}. Searching the bus again…</source>
            <translation>Přiděleno a uloženo: {0}. Sběrnice se prohledává znovu…</translation>
        </message>
        <message>
            <source>Serial {0} answers as {1} (stored). Going online with it…</source>
            <translation>Sériové číslo {0} odpovídá jako {1} (uloženo). Přechod do režimu online…</translation>
        </message>
    </context>
    <context>
        <name>MainActions</name>
        <message>
            <source>&amp;New…</source>
            <translation>&amp;Nový…</translation>
        </message>
        <message>
            <source>New parameter set from a valve type key</source>
            <translation>Nový záznam parametrů podle typového klíče ventilu</translation>
        </message>
        <message>
            <source>&amp;Open…</source>
            <translation>&amp;Otevřít…</translation>
        </message>
        <message>
            <source>Open a parameter file (*.prm)</source>
            <translation>Načtení záznamu parametrů (*.prm)</translation>
        </message>
        <message>
            <source>&amp;Save</source>
            <translation>&amp;Uložit</translation>
        </message>
        <message>
            <source>Save the parameter file (*.prm)</source>
            <translation>Uložení záznamu parametrů (*.prm)</translation>
        </message>
        <message>
            <source>Save &amp;As…</source>
            <translation>Uložit &amp;jako…</translation>
        </message>
        <message>
            <source>Save the parameters under another name</source>
            <translation>Uložení záznamu parametrů pod jiným jménem</translation>
        </message>
        <message>
            <source>Save bac&amp;kup copy…</source>
            <translation>Uložit zá&amp;ložní kopii…</translation>
        </message>
        <message>
            <source>Save a copy of the parameters to another file; you keep working on this one</source>
            <translation>Uložení kopie parametrů do jiného souboru; dále se pracuje s tímto</translation>
        </message>
        <message>
            <source>&amp;Undo</source>
            <translation>&amp;Zpět</translation>
        </message>
        <message>
            <source>Undo the last change</source>
            <translation>Vrátit poslední změnu</translation>
        </message>
        <message>
            <source>&amp;Redo</source>
            <translation>Zno&amp;vu</translation>
        </message>
        <message>
            <source>Redo the change undone last</source>
            <translation>Znovu provést naposledy vrácenou změnu</translation>
        </message>
        <message>
            <source>&amp;Print…</source>
            <translation>&amp;Tisk…</translation>
        </message>
        <message>
            <source>Print the current parameter record</source>
            <translation>Vytisknout aktuální záznam parametrů</translation>
        </message>
        <message>
            <source>Object &amp;dictionary…</source>
            <translation>Slov&amp;ník objektů…</translation>
        </message>
        <message>
            <source>Read, and at Expert level write, any object of the valve</source>
            <translation>Číst a na expertní úrovni zapisovat libovolný objekt ventilu</translation>
        </message>
        <message>
            <source>Export &amp;DCF…</source>
            <translation>Export &amp;DCF…</translation>
        </message>
        <message>
            <source>Save the valve's CANopen configuration as a CiA 306 DCF (for a PLC configurator)</source>
            <translation>Uložit konfiguraci CANopen ventilu jako DCF podle CiA 306 (pro konfigurátor PLC)</translation>
        </message>
        <message>
            <source>&amp;Export PDF…</source>
            <translation>&amp;Export do PDF…</translation>
        </message>
        <message>
            <source>Save the parameter record as PDF</source>
            <translation>Uložit protokol parametrů jako PDF</translation>
        </message>
        <message>
            <source>E&amp;xit</source>
            <translation>&amp;Konec</translation>
        </message>
        <message>
            <source>Quit prm9tool</source>
            <translation>Ukončit prm9tool</translation>
        </message>
        <message>
            <source>&amp;Flow diagram</source>
            <translation>&amp;Postupový diagram</translation>
        </message>
        <message>
            <source>Show the signal-flow diagram</source>
            <translation>Zobrazení signálového diagramu</translation>
        </message>
        <message>
            <source>&amp;Parameter list</source>
            <translation>&amp;Seznam parametrů</translation>
        </message>
        <message>
            <source>Show all parameters as a table</source>
            <translation>Zobrazení všech parametrů v tabulce</translation>
        </message>
        <message>
            <source>&amp;Oscilloscope</source>
            <translation>&amp;Osciloskop</translation>
        </message>
        <message>
            <source>Show values in real time (online mode only)</source>
            <translation>Zobrazení hodnot v reálném čase (pouze v režimu online)</translation>
        </message>
        <message>
            <source>&amp;CANopen window…</source>
            <translation>Okno &amp;CANopen…</translation>
        </message>
        <message>
            <source>CANopen settings of the valve</source>
            <translation>Nastavení CANopen ventilu</translation>
        </message>
        <message>
            <source>&amp;Basic</source>
            <translation>&amp;Základní</translation>
        </message>
        <message>
            <source>Basic parameter settings</source>
            <translation>Základní možnosti nastavování parametrů ventilu</translation>
        </message>
        <message>
            <source>&amp;Expert…</source>
            <translation>&amp;Expertní…</translation>
        </message>
        <message>
            <source>All settings including controllers and linearization</source>
            <translation>Další možnosti nastavování parametrů (včetně regulátorů a linearizace)</translation>
        </message>
        <message>
            <source>&amp;Change Expert password…</source>
            <translation>Změnit &amp;heslo pro expertní úroveň…</translation>
        </message>
        <message>
            <source>Valve &amp;selection…</source>
            <translation>&amp;Výběr ventilu…</translation>
        </message>
        <message>
            <source>Choose the valve configuration by its type key</source>
            <translation>Výběr konfigurace ventilu pomocí typového klíče</translation>
        </message>
        <message>
            <source>Valve s&amp;tatus…</source>
            <translation>S&amp;tav ventilu…</translation>
        </message>
        <message>
            <source>State, firmware, serial number and errors of the valve</source>
            <translation>Stav, verze firmware, výrobní číslo a chyby ventilu</translation>
        </message>
        <message>
            <source>&amp;Upload to valve</source>
            <translation>&amp;Načtení do ventilu</translation>
        </message>
        <message>
            <source>Write the parameters into the valve</source>
            <translation>Zápis dat z programu do elektroniky ventilu</translation>
        </message>
        <message>
            <source>&amp;Download from valve</source>
            <translation>&amp;Stažení z ventilu</translation>
        </message>
        <message>
            <source>Read the parameters of the valve into the program</source>
            <translation>Načtení parametrů z elektroniky ventilu do programu</translation>
        </message>
        <message>
            <source>St&amp;ore in valve</source>
            <translation>&amp;Uložit do paměti ventilu</translation>
        </message>
        <message>
            <source>Make the values the valve works with permanent: they stay after a restart</source>
            <translation>Trvalé uložení hodnot, se kterými ventil pracuje: zůstanou zachovány i po restartu</translation>
        </message>
        <message>
            <source>Restore &amp;factory values…</source>
            <translation>&amp;Obnovit tovární nastavení…</translation>
        </message>
        <message>
            <source>Return the parameters to the factory values</source>
            <translation>Vrácení parametrů na tovární hodnoty</translation>
        </message>
        <message>
            <source>&amp;Restart valve…</source>
            <translation>&amp;Restart ventilu…</translation>
        </message>
        <message>
            <source>Restart the valve electronics (only with the hydraulics disconnected)</source>
            <translation>Restartování elektroniky ventilu (dovoleno pouze při odpojeném hydraulickém obvodu)</translation>
        </message>
        <message>
            <source>&amp;Verify by restart…</source>
            <translation>Ověř&amp;it restartem…</translation>
        </message>
        <message>
            <source>After an upload: restart the valve (hydraulics disconnected) and read back that it kept the values</source>
            <translation>Po načtení do ventilu: restartovat ventil (hydraulika odpojena) a zpětně načíst, zda si hodnoty ponechal</translation>
        </message>
        <message>
            <source>&amp;HID configuration…</source>
            <translation>Konfigurace &amp;HID…</translation>
        </message>
        <message>
            <source>Choose the valve to communicate with</source>
            <translation>Výběr ventilu pro komunikaci</translation>
        </message>
        <message>
            <source>&amp;CAN bus…</source>
            <translation>Sběrnice &amp;CAN…</translation>
        </message>
        <message>
            <source>Find the valves on a CAN bus and go online with one (CANopen)</source>
            <translation>Najít ventily na sběrnici CAN a přejít s jedním do režimu online (CANopen)</translation>
        </message>
        <message>
            <source>CAN &amp;trace…</source>
            <translation>CAN &amp;záznam…</translation>
        </message>
        <message>
            <source>Record the CAN bus, or read a trace file in words</source>
            <translation>Zaznamenat sběrnici CAN nebo přečíst soubor záznamu slovy</translation>
        </message>
        <message>
            <source>O&amp;nline mode</source>
            <translation>Režim o&amp;nline</translation>
        </message>
        <message>
            <source>Connect to the valve</source>
            <translation>Přechod do režimu online</translation>
        </message>
        <message>
            <source>O&amp;ffline mode</source>
            <translation>Režim o&amp;ffline</translation>
        </message>
        <message>
            <source>Disconnect from the valve</source>
            <translation>Odpojení od elektroniky ventilu</translation>
        </message>
        <message>
            <source>&amp;Help</source>
            <translation>&amp;Nápověda</translation>
        </message>
        <message>
            <source>How to use prm9tool</source>
            <translation>Jak používat prm9tool</translation>
        </message>
        <message>
            <source>Home&amp;page</source>
            <translation>&amp;Domovská stránka</translation>
        </message>
        <message>
            <source>Open the manufacturer's homepage</source>
            <translation>Otevřít domovskou stránku výrobce</translation>
        </message>
        <message>
            <source>&amp;About prm9tool</source>
            <translation>&amp;O programu prm9tool</translation>
        </message>
        <message>
            <source>Versions and contact</source>
            <translation>Verze a kontakt</translation>
        </message>
        <message>
            <source>Not while online: go offline first, then choose the valve to communicate with</source>
            <translation>Ne v režimu online: nejprve přejděte do režimu offline, pak zvolte ventil pro komunikaci</translation>
        </message>
        <message>
            <source>&amp;File</source>
            <translation>&amp;Soubor</translation>
        </message>
        <message>
            <source>&amp;View</source>
            <translation>Ná&amp;hled</translation>
        </message>
        <message>
            <source>V&amp;alve</source>
            <translation>&amp;Ventil</translation>
        </message>
        <message>
            <source>&amp;Communication</source>
            <translation>&amp;Komunikace</translation>
        </message>
        <message>
            <source>Open re&amp;cent</source>
            <translation>Na&amp;posledy otevřené</translation>
        </message>
        <message>
            <source>&amp;Access level</source>
            <translation>Ú&amp;roveň oprávnění</translation>
        </message>
        <message>
            <source>&amp;Language</source>
            <translation>&amp;Jazyk</translation>
        </message>
        <message>
            <source>Toolbar</source>
            <translation>Panel nástrojů</translation>
        </message>
        <message>
            <source>Co&amp;mpare with file…</source>
            <translation>Po&amp;rovnat se souborem…</translation>
        </message>
        <message>
            <source>Expor&amp;t EDS…</source>
            <translation>Export ED&amp;S…</translation>
        </message>
        <message>
            <source>Save the valve type's CiA 306 EDS (for a PLC configurator)</source>
            <translation>Uložit EDS typu ventilu podle CiA 306 (pro konfigurátor PLC)</translation>
        </message>
        <message>
            <source>Compare the parameters with a *.prm file, take chosen values</source>
            <translation>Porovnat parametry se souborem *.prm, převzít zvolené hodnoty</translation>
        </message>
        <message>
            <source>&amp;Compare with valve</source>
            <translation>&amp;Porovnat s ventilem</translation>
        </message>
        <message>
            <source>Compare the document with the valve, apply chosen values</source>
            <translation>Porovnat dokument s ventilem, použít zvolené hodnoty</translation>
        </message>
        <message>
            <source>&amp;History…</source>
            <translation>&amp;Historie…</translation>
        </message>
        <message>
            <source>Every operation recorded on a valve's parameters</source>
            <translation>Každá zaznamenaná operace s parametry ventilu</translation>
        </message>
    </context>
    <context>
        <name>MainStatusBar</name>
        <message>
            <source>ONLINE</source>
            <translation>ONLINE</translation>
        </message>
        <message>
            <source>OFFLINE</source>
            <translation>OFFLINE</translation>
        </message>
        <message>
            <source>CONNECTING</source>
            <translation>PŘIPOJOVÁNÍ</translation>
        </message>
        <message>
            <source>Mode: {0}</source>
            <translation>Režim: {0}</translation>
        </message>
        <message>
            <source>Connected, but the document and the valve do not agree yet: edits are not sent to the valve</source>
            <translation>Připojeno, ale dokument a ventil se zatím neshodují: změny se do ventilu neposílají</translation>
        </message>
        <message>
            <source>RECONNECTING… {0} s</source>
            <translation>OBNOVA SPOJENÍ… {0} s</translation>
        </message>
        <message>
            <source>The link to the valve {0} broke. prm9tool looks for it and compares when it is back; nothing is written to the valve without you.</source>
            <translation>Spojení s ventilem {0} se přerušilo. prm9tool jej hledá a po jeho návratu jej porovná s dokumentem; bez vás se do ventilu nic nezapíše.</translation>
        </message>
        <message>
            <source>Expert</source>
            <translation>Expertní</translation>
        </message>
        <message>
            <source>Basic</source>
            <translation>Základní</translation>
        </message>
        <message>
            <source>Level: {0}</source>
            <translation>Úroveň: {0}</translation>
        </message>
        <message>
            <source>Status: {0}</source>
            <translation>Status: {0}</translation>
        </message>
        <message>
            <source>FW: {0}</source>
            <translation>Verze FW: {0}</translation>
        </message>
        <message>
            <source>untitled</source>
            <translation>nepojmenovaná</translation>
        </message>
        <message numerus="yes">
            <source>%n sample(s) lost</source>
            <translation>
                <numerusform>%n vzorek ztracen</numerusform>
                <numerusform>%n vzorky ztraceny</numerusform>
                <numerusform>%n vzorků ztraceno</numerusform>
            </translation>
        </message>
        <message>
            <source>The oscilloscope stream lost samples: the USB link or the computer could not keep up. The curves have gaps there.</source>
            <translation>Osciloskopu se ztratily vzorky: spojení USB nebo počítač nestíhaly. Křivky mají v těchto místech mezery.</translation>
        </message>
    </context>
    <context>
        <name>MainWindow</name>
        <message>
            <source>The oscilloscope records in the background: the valve sends three measuring points at a time, so the diagram's other points show — until the recording stops.</source>
            <translation>Osciloskop zaznamenává na pozadí: ventil posílá tři měřicí body najednou, proto ostatní měřicí body diagramu ukazují — až do konce záznamu.</translation>
        </message>
        <message>
            <source>The oscilloscope works in online mode only.</source>
            <translation>Osciloskop je dostupný pouze v režimu online.</translation>
        </message>
        <message>
            <source>untitled</source>
            <translation>nepojmenovaná</translation>
        </message>
        <message>
            <source>prm9tool</source>
            <translation>prm9tool</translation>
        </message>
        <message>
            <source>Parameterization of PRM9 proportional directional valves.</source>
            <translation>Nastavení parametrů proporcionálních rozváděčů PRM9.</translation>
        </message>
        <message>
            <source>Free software under the GNU General Public License v3 or later.</source>
            <translation>Svobodný software pod licencí GNU General Public License v3 nebo novější.</translation>
        </message>
        <message>
            <source>About prm9tool</source>
            <translation>O programu prm9tool</translation>
        </message>
    </context>
    <context>
        <name>ObjectDictionaryDialog</name>
        <message>
            <source>Object dictionary</source>
            <translation>Slovník objektů</translation>
        </message>
        <message>
            <source>Index</source>
            <translation>Index</translation>
        </message>
        <message>
            <source>Sub</source>
            <translation>Subindex</translation>
        </message>
        <message>
            <source>Name</source>
            <translation>Název</translation>
        </message>
        <message>
            <source>Type</source>
            <translation>Typ</translation>
        </message>
        <message>
            <source>Access</source>
            <translation>Přístup</translation>
        </message>
        <message>
            <source>Value</source>
            <translation>Hodnota</translation>
        </message>
        <message>
            <source>Search: index, name, type or value</source>
            <translation>Hledat: index, název, typ nebo hodnota</translation>
        </message>
        <message>
            <source>Read all</source>
            <translation>Číst vše</translation>
        </message>
        <message>
            <source>Double-click a writable object to write it.</source>
            <translation>Zapisovatelný objekt zapíšete dvojklikem.</translation>
        </message>
        <message>
            <source>Reading only: writing needs the Expert level.</source>
            <translation>Jen čtení: zápis vyžaduje expertní úroveň.</translation>
        </message>
        <message>
            <source>— (no entry)</source>
            <translation>— (žádný záznam)</translation>
        </message>
        <message>
            <source>Write {0}</source>
            <translation>Zapsat {0}</translation>
        </message>
        <message>
            <source>{0} ({1}), raw value:</source>
            <translation>{0} ({1}), surová hodnota:</translation>
        </message>
    </context>
    <context>
        <name>OnlineDiffDialog</name>
        <message>
            <source>Document and valve differ</source>
            <translation>Dokument a ventil se liší</translation>
        </message>
        <message>
            <source>Take the valve's values</source>
            <translation>Převzít hodnoty ventilu</translation>
        </message>
        <message>
            <source>Send the document's values</source>
            <translation>Odeslat hodnoty dokumentu</translation>
        </message>
        <message>
            <source>The document is for another valve variant; it cannot be sent.</source>
            <translation>Dokument je pro jinou variantu ventilu; nelze jej odeslat.</translation>
        </message>
        <message numerus="yes">
            <source>%n value(s) in the document differ from the valve.</source>
            <translation>
                <numerusform>%n hodnota v dokumentu se liší od ventilu.</numerusform>
                <numerusform>%n hodnoty v dokumentu se liší od ventilu.</numerusform>
                <numerusform>%n hodnot v dokumentu se liší od ventilu.</numerusform>
            </translation>
        </message>
        <message>
            <source>Document type key: {0} — valve type key: {1}</source>
            <translation>Typový klíč dokumentu: {0} – typový klíč ventilu: {1}</translation>
        </message>
        <message>
            <source>The valve is of another variant: only its values can be taken.</source>
            <translation>Ventil je jiné varianty: lze pouze převzít jeho hodnoty.</translation>
        </message>
        <message>
            <source>Cancel stays offline; the document is not changed and nothing is written.</source>
            <translation>Zrušit ponechá režim offline; dokument se nezmění a nic se nezapíše.</translation>
        </message>
        <message>
            <source>Mnemonic</source>
            <translation>Zkratka</translation>
        </message>
        <message>
            <source>Description</source>
            <translation>Popis</translation>
        </message>
        <message>
            <source>Document</source>
            <translation>Dokument</translation>
        </message>
        <message>
            <source>Valve</source>
            <translation>Ventil</translation>
        </message>
        <message>
            <source>Choose per parameter…</source>
            <translation>Zvolit po parametrech…</translation>
        </message>
    </context>
    <context>
        <name>OperationProgress</name>
        <message>
            <source>Cancel</source>
            <translation>Zrušit</translation>
        </message>
    </context>
    <context>
        <name>PagedPrint</name>
        <message>
            <source>Page {0} of {1}</source>
            <translation>Strana {0} z {1}</translation>
        </message>
    </context>
    <context>
        <name>ParameterEditDialog</name>
        <message>
            <source>Parameter {0}</source>
            <translation>Parametr {0}</translation>
        </message>
        <message>
            <source>Current value:</source>
            <translation>Aktuální hodnota:</translation>
        </message>
        <message>
            <source>Allowed range:</source>
            <translation>Přípustný rozsah:</translation>
        </message>
        <message>
            <source>Factory default:</source>
            <translation>Tovární nastavení:</translation>
        </message>
        <message>
            <source>New value:</source>
            <translation>Nová hodnota:</translation>
        </message>
        <message>
            <source>At Basic access level all ramps are set together: {0}.</source>
            <translation>Na základní úrovni oprávnění se všechny rampy nastavují společně: {0}.</translation>
        </message>
        <message>
            <source>Read-only value of the valve.</source>
            <translation>Hodnota ventilu pouze pro čtení.</translation>
        </message>
        <message>
            <source>Can only be changed at Expert access level.</source>
            <translation>Lze změnit pouze na expertní úrovni oprávnění.</translation>
        </message>
        <message>
            <source>{0}: “{1}” is not a number.</source>
            <translation>{0}: „{1}“ není číslo.</translation>
        </message>
        <message>
            <source>{0}: {1}{2} is outside the allowed range {3}{2}.</source>
            <translation>{0}: {1}{2} je mimo přípustný rozsah {3}{2}.</translation>
        </message>
    </context>
    <context>
        <name>ParameterListView</name>
        <message>
            <source>Search mnemonic or description…</source>
            <translation>Hledat zkratku nebo popis…</translation>
        </message>
        <message>
            <source>Modified only</source>
            <translation>Jen změněné</translation>
        </message>
        <message>
            <source>Show only the values that differ from the factory defaults</source>
            <translation>Zobrazit jen hodnoty odlišné od továrního nastavení</translation>
        </message>
    </context>
    <context>
        <name>ParameterTableModel</name>
        <message>
            <source>Mnemonic</source>
            <translation>Zkratka</translation>
        </message>
        <message>
            <source>Description</source>
            <translation>Popis</translation>
        </message>
        <message>
            <source>Value</source>
            <translation>Hodnota</translation>
        </message>
        <message>
            <source>Unit</source>
            <translation>Jednotka</translation>
        </message>
        <message>
            <source>Range: {0} … {1} {2}</source>
            <translation>Rozsah: {0} … {1} {2}</translation>
        </message>
        <message>
            <source>Factory default: {0} {1}</source>
            <translation>Tovární nastavení: {0} {1}</translation>
        </message>
        <message>
            <source>Read-only value of the valve.</source>
            <translation>Hodnota ventilu pouze pro čtení.</translation>
        </message>
        <message>
            <source>Can only be changed at Expert access level.</source>
            <translation>Lze změnit pouze na expertní úrovni oprávnění.</translation>
        </message>
    </context>
    <context>
        <name>PasswordDialog</name>
        <message>
            <source>Expert access level</source>
            <translation>Expertní úroveň oprávnění</translation>
        </message>
        <message>
            <source>The Expert level unlocks the controllers and the linearizations. Changing them needs the appropriate qualification.</source>
            <translation>Expertní úroveň zpřístupní regulátory a linearizace. Jejich změna vyžaduje odpovídající kvalifikaci.</translation>
        </message>
        <message>
            <source>The password as delivered is written in the help, under “Access levels” (F1, or &lt;a href=&quot;help&quot;&gt;open the help&lt;/a&gt;). A password changed since is known to whoever changed it.</source>
            <translation>Heslo ve stavu při dodání je uvedeno v nápovědě v části „Úrovně oprávnění“ (F1 nebo &lt;a href=&quot;help&quot;&gt;otevřít nápovědu&lt;/a&gt;). Heslo změněné od té doby zná ten, kdo je změnil.</translation>
        </message>
        <message>
            <source>Password:</source>
            <translation>Heslo:</translation>
        </message>
        <message>
            <source>Wrong password.</source>
            <translation>Chybné heslo.</translation>
        </message>
    </context>
    <context>
        <name>Problems</name>
        <message>
            <source>{0} two coils{1}</source>
            <translation>{0} dvě cívky{1}</translation>
        </message>
        <message>
            <source>{0} coil A{1}</source>
            <translation>{0} cívka A{1}</translation>
        </message>
        <message>
            <source>{0} coil B{1}</source>
            <translation>{0} cívka B{1}</translation>
        </message>
        <message>
            <source>{0}: 'value over CANopen' needs a -CA valve</source>
            <translation>{0}: „hodnota přes CANopen“ vyžaduje ventil -CA</translation>
        </message>
        <message>
            <source>AINSETP: {0} is not a recommended setpoint type for {1} valves (manual table 8-4)</source>
            <translation>AINSETP: {0} není doporučený typ signálu žádané hodnoty pro ventily {1} (návod, tabulka 8-4)</translation>
        </message>
        <message>
            <source>{0} = {1} mA is above the nominal coil current CURNORM = {2} mA</source>
            <translation>{0} = {1} mA je vyšší než jmenovitý proud cívky CURNORM = {2} mA</translation>
        </message>
        <message>
            <source>{0}: {1} equals {2}; X points must differ</source>
            <translation>{0}: {1} se rovná {2}; body X se musí lišit</translation>
        </message>
        <message>
            <source>{0} linearization points must increase strictly: {1} &lt; {2}</source>
            <translation>{0}: body linearizace musí ostře stoupat: {1} &lt; {2}</translation>
        </message>
        <message>
            <source>{0} linearization outputs must not decrease: {1} &lt; {2}</source>
            <translation>{0}: výstupní hodnoty linearizace nesmí klesat: {1} &lt; {2}</translation>
        </message>
        <message>
            <source>{0}: {1} is not a number</source>
            <translation>{0}: {1} není číslo</translation>
        </message>
        <message>
            <source>{0}: {1} is far outside the range</source>
            <translation>{0}: {1} je daleko mimo rozsah</translation>
        </message>
        <message>
            <source>{0}: {1} is not a number: the decimals follow a point ({2})</source>
            <translation>{0}: {1} není číslo: desetinná místa následují za tečkou ({2})</translation>
        </message>
        <message>
            <source>{0}: expected text, got {1}</source>
            <translation>{0}: očekáván text, zadáno: {1}</translation>
        </message>
        <message>
            <source>{0}: expected a number, got {1}</source>
            <translation>{0}: očekáváno číslo, zadáno: {1}</translation>
        </message>
        <message>
            <source>{0}: {1} is not one of the allowed codes {2}</source>
            <translation>{0}: {1} není žádný z přípustných kódů {2}</translation>
        </message>
        <message>
            <source>{0}: {1}{2} is outside the allowed range {3} … {4}{2}</source>
            <translation>{0}: {1}{2} je mimo přípustný rozsah {3} … {4}{2}</translation>
        </message>
        <message>
            <source>{0}: no such parameter on a {1} valve</source>
            <translation>{0}: ventil {1} tento parametr nemá</translation>
        </message>
        <message>
            <source>{0}:{1}: warning: {2}</source>
            <translation>{0}:{1}: varování: {2}</translation>
        </message>
        <message>
            <source>expected {0} as the first entry: not a prm9tool parameter file, or its header is damaged</source>
            <translation>jako první položka očekáváno {0}: nejde o záznam parametrů prm9tool, nebo je poškozena jeho hlavička</translation>
        </message>
        <message>
            <source>format {0} is unknown; expected {1}</source>
            <translation>formát {0} je neznámý; očekáváno: {1}</translation>
        </message>
        <message>
            <source>format version {0} is newer than this prm9tool reads ({1}): update prm9tool</source>
            <translation>verze formátu {0} je novější, než jakou tento prm9tool čte ({1}): aktualizujte prm9tool</translation>
        </message>
        <message>
            <source>format version {0} does not exist</source>
            <translation>verze formátu {0} neexistuje</translation>
        </message>
        <message>
            <source>no 'type_key = ...' entry: the header is incomplete</source>
            <translation>chybí položka 'type_key = ...': hlavička je neúplná</translation>
        </message>
        <message>
            <source>serial {0} must be a whole number {1} … {2}</source>
            <translation>výrobní číslo {0} musí být celé číslo {1} … {2}</translation>
        </message>
        <message>
            <source>firmware is empty; the line is left out when saving</source>
            <translation>firmware je prázdný; při uložení se řádek vynechá</translation>
        </message>
        <message>
            <source>unknown parameter {0}: kept and written back unchanged</source>
            <translation>neznámý parametr {0}: ponechá se a zapíše zpět beze změny</translation>
        </message>
        <message>
            <source>unknown parameter {0}: kept and written back unchanged (did you mean {1}?)</source>
            <translation>neznámý parametr {0}: ponechá se a zapíše zpět beze změny (měli jste na mysli {1}?)</translation>
        </message>
        <message>
            <source>{0} ({1}) is a read-only value, not a setting a parameter file can hold</source>
            <translation>{0} ({1}) je hodnota pouze pro čtení, ne nastavení, které může záznam parametrů obsahovat</translation>
        </message>
        <message>
            <source>{0} ({1}) is set online only and does not belong in a parameter file</source>
            <translation>{0} ({1}) se nastavuje pouze v režimu online a do záznamu parametrů nepatří</translation>
        </message>
        <message>
            <source>{0} ({1}) does not exist on {2} valves (type key {3}); remove the line or change the type key</source>
            <translation>{0} ({1}) u ventilů {2} neexistuje (typový klíč {3}); odstraňte řádek nebo změňte typový klíč</translation>
        </message>
        <message>
            <source>{0} ({1}) is not a parameter of {2} valves (type key {3}): they have the object but no external sensor input; remove the line or change the type key</source>
            <translation>{0} ({1}) není parametrem ventilů {2} (typový klíč {3}): mají objekt, ale žádný vstup externího snímače; odstraňte řádek nebo změňte typový klíč</translation>
        </message>
        <message>
            <source>{0}: no value after '='</source>
            <translation>{0}: za '=' chybí hodnota</translation>
        </message>
        <message>
            <source>{0}: {1}{2} is stored as {3}{2}, the nearest value the valve can hold</source>
            <translation>{0}: {1}{2} se uloží jako {3}{2}, nejbližší hodnota, kterou ventil dokáže uložit</translation>
        </message>
        <message>
            <source>{0} has no value: the valve it was read from does not have it over CANopen; not uploaded</source>
            <translation>{0} nemá hodnotu: ventil, ze kterého byl načten, ji přes CANopen nemá; nenačte se do ventilu</translation>
        </message>
        <message>
            <source>{0} ({1}) is missing (required for {2} valves)</source>
            <translation>{0} ({1}) chybí (povinný pro ventily {2})</translation>
        </message>
        <message>
            <source>{0}: no value after '='; only a download over CANopen may leave a value out, marked with the comment '{1}'</source>
            <translation>{0}: za '=' chybí hodnota; hodnotu smí vynechat jen načtení přes CANopen, označené komentářem '{1}'</translation>
        </message>
        <message>
            <source>byte 0x{0} is not UTF-8 text: the file is corrupt</source>
            <translation>bajt 0x{0} není text UTF-8: soubor je poškozený</translation>
        </message>
        <message>
            <source>control character U+{0}: binary data, the file is corrupt</source>
            <translation>řídicí znak U+{0}: binární data, soubor je poškozený</translation>
        </message>
        <message>
            <source>text after the checksum line, which must be the last line</source>
            <translation>text za řádkem kontrolního součtu, který musí být poslední</translation>
        </message>
        <message>
            <source>garbled line: expected 'NAME = value', a '#' comment or a blank line</source>
            <translation>nečitelný řádek: očekáváno 'NÁZEV = hodnota', komentář '#' nebo prázdný řádek</translation>
        </message>
        <message>
            <source>{0} is set twice (first on line {1})</source>
            <translation>{0} je nastaven dvakrát (poprvé na řádku {1})</translation>
        </message>
        <message>
            <source>no value for {0}, which every {1} file holds: these are not the values of such a valve</source>
            <translation>chybí hodnota {0}, kterou obsahuje každý soubor pro {1}: nejsou to hodnoty takového ventilu</translation>
        </message>
        <message>
            <source>too large to be a parameter file ({0} bytes, more than {1})</source>
            <translation>příliš velký na záznam parametrů ({0} bajtů, více než {1})</translation>
        </message>
        <message>
            <source>the file is empty</source>
            <translation>soubor je prázdný</translation>
        </message>
        <message>
            <source>no 'checksum = ...' line at the end: the file is truncated (a file written by hand must end with one, e.g. 'checksum = crc32:00000000')</source>
            <translation>na konci chybí řádek 'checksum = ...': soubor je zkrácený (ručně psaný soubor musí takovým řádkem končit, např. 'checksum = crc32:00000000')</translation>
        </message>
        <message>
            <source>checksum {0} is damaged (expected crc32: and 8 hex digits)</source>
            <translation>kontrolní součet {0} je poškozený (očekáváno: crc32: a 8 šestnáctkových číslic)</translation>
        </message>
        <message>
            <source>checksum does not match: the file was changed outside prm9tool (edited by hand?); saving it from prm9tool writes a new checksum</source>
            <translation>kontrolní součet nesouhlasí: soubor byl změněn mimo prm9tool (ručně upraven?); uložením z prm9tool se zapíše nový kontrolní součet</translation>
        </message>
        <message>
            <source>cannot read the file: {0}</source>
            <translation>soubor nelze přečíst: {0}</translation>
        </message>
        <message>
            <source>cannot save the file: {0}</source>
            <translation>soubor nelze uložit: {0}</translation>
        </message>
        <message>
            <source>{0}: {1} is ambiguous (a thousands separator?); write the number without one, with '{2}' before the decimals</source>
            <translation>{0}: {1} je nejednoznačné (oddělovač tisíců?); napište číslo bez něj, s „{2}“ před desetinnými místy</translation>
        </message>
        <message>
            <source>unreadable EEPROM image of an emulated valve: {0}</source>
            <translation>nečitelný obraz EEPROM emulovaného ventilu: {0}</translation>
        </message>
        <message>
            <source>not an emulator EEPROM image (format {0})</source>
            <translation>není to obraz EEPROM emulátoru (formát {0})</translation>
        </message>
        <message>
            <source>unsupported EEPROM image version {0}</source>
            <translation>nepodporovaná verze obrazu EEPROM {0}</translation>
        </message>
        <message>
            <source>the image belongs to a {0} valve, not to {1}: give the emulated valve another serial (TYPEKEY:SERIAL) or delete the file</source>
            <translation>obraz patří ventilu {0}, ne {1}: dejte emulovanému ventilu jiné výrobní číslo (TYPOVÝ_KLÍČ:ČÍSLO) nebo soubor smažte</translation>
        </message>
        <message>
            <source>the EEPROM image has no 'values' table</source>
            <translation>obraz EEPROM nemá tabulku 'values'</translation>
        </message>
    </context>
    <context>
        <name>RampsDialog</name>
        <message>
            <source>All ramps (for a 100 % step)</source>
            <translation>Všechny rampy (pro skok 100 %)</translation>
        </message>
        <message>
            <source>the ramps differ</source>
            <translation>rampy se liší</translation>
        </message>
        <message>
            <source>Basic access level: one time sets all ramps. Expert level sets each ramp on its own.</source>
            <translation>Základní úroveň: jeden čas nastaví všechny rampy. Na expertní úrovni se každá rampa nastavuje samostatně.</translation>
        </message>
        <message>
            <source>Each time is for a 100 % step; a 50 % step takes half as long.</source>
            <translation>Každý čas platí pro skok 100 %; skok 50 % trvá poloviční dobu.</translation>
        </message>
        <message>
            <source>100 % step</source>
            <translation>skok 100 %</translation>
        </message>
        <message>
            <source>50 % step</source>
            <translation>skok 50 %</translation>
        </message>
        <message>
            <source>Time (ms)</source>
            <translation>Čas (ms)</translation>
        </message>
        <message>
            <source>Demand value (%)</source>
            <translation>Hodnota požadavku (%)</translation>
        </message>
    </context>
    <context>
        <name>Record</name>
        <message>
            <source>serial number {0}</source>
            <translation>výrobní číslo {0}</translation>
        </message>
        <message>
            <source>PRM9 parameter record</source>
            <translation>Protokol parametrů PRM9</translation>
        </message>
        <message>
            <source>untitled</source>
            <translation>nepojmenovaná</translation>
        </message>
        <message>
            <source>untitled (the values are not saved in a file)</source>
            <translation>nepojmenovaná (hodnoty nejsou uloženy v žádném souboru)</translation>
        </message>
        <message>
            <source>{0} (changed, not saved: the file holds another valve type)</source>
            <translation>{0} (změněno, neuloženo: soubor obsahuje jiný typ ventilu)</translation>
        </message>
        <message>
            <source>{0} (changed, not saved: the values marked {1} differ from the file)</source>
            <translation>{0} (změněno, neuloženo: hodnoty označené {1} se liší od souboru)</translation>
        </message>
        <message>
            <source>Type key</source>
            <translation>Typový klíč</translation>
        </message>
        <message>
            <source>Serial number</source>
            <translation>Výrobní číslo</translation>
        </message>
        <message>
            <source>Firmware</source>
            <translation>Firmware</translation>
        </message>
        <message>
            <source>File</source>
            <translation>Soubor</translation>
        </message>
        <message>
            <source>Date</source>
            <translation>Datum</translation>
        </message>
        <message>
            <source>Access level</source>
            <translation>Úroveň oprávnění</translation>
        </message>
        <message>
            <source>Mnemonic</source>
            <translation>Zkratka</translation>
        </message>
        <message>
            <source>Description</source>
            <translation>Popis</translation>
        </message>
        <message>
            <source>Value</source>
            <translation>Hodnota</translation>
        </message>
        <message>
            <source>Unit</source>
            <translation>Jednotka</translation>
        </message>
        <message>
            <source>Date:</source>
            <translation>Datum:</translation>
        </message>
        <message>
            <source>Name:</source>
            <translation>Jméno:</translation>
        </message>
        <message>
            <source>Signature:</source>
            <translation>Podpis:</translation>
        </message>
    </context>
    <context>
        <name>RecordActions</name>
        <message>
            <source>Expert</source>
            <translation>Expertní</translation>
        </message>
        <message>
            <source>Basic</source>
            <translation>Základní</translation>
        </message>
        <message>
            <source>Parameter record printed</source>
            <translation>Protokol parametrů vytištěn</translation>
        </message>
        <message>
            <source>Export PDF</source>
            <translation>Export do PDF</translation>
        </message>
        <message>
            <source>PDF files (*.pdf)</source>
            <translation>Soubory PDF (*.pdf)</translation>
        </message>
        <message>
            <source>Cannot write “{0}”: {1}</source>
            <translation>„{0}“ nelze zapsat: {1}</translation>
        </message>
        <message>
            <source>Parameter record saved as {0}</source>
            <translation>Protokol parametrů uložen jako {0}</translation>
        </message>
        <message>
            <source>PRM9 parameter record {0}</source>
            <translation>Protokol parametrů PRM9 {0}</translation>
        </message>
    </context>
    <context>
        <name>RecordControls</name>
        <message>
            <source>Record…</source>
            <translation>Zaznamenat…</translation>
        </message>
        <message>
            <source>Record every frame of the CAN bus into a trace file</source>
            <translation>Zaznamenat každý rámec sběrnice CAN do souboru záznamu</translation>
        </message>
        <message>
            <source>Stop recording</source>
            <translation>Ukončit záznam</translation>
        </message>
        <message>
            <source>Opening the CAN bus…</source>
            <translation>Otevírá se sběrnice CAN…</translation>
        </message>
        <message>
            <source>Record the CAN bus</source>
            <translation>Zaznamenat sběrnici CAN</translation>
        </message>
        <message>
            <source>CAN traces ({0})</source>
            <translation>Záznamy CAN ({0})</translation>
        </message>
        <message>
            <source>Recording into {0}: {1} frames</source>
            <translation>Záznam do {0}: {1} rámců</translation>
        </message>
        <message>
            <source>{0} frames recorded into {1}</source>
            <translation>{0} rámců zaznamenáno do {1}</translation>
        </message>
        <message>
            <source>Not recording: {0}</source>
            <translation>Nezaznamenává se: {0}</translation>
        </message>
    </context>
    <context>
        <name>RecordDetailsDialog</name>
        <message>
            <source>History record {0} of valve {1}</source>
            <translation>Záznam historie {0} ventilu {1}</translation>
        </message>
        <message>
            <source>What was done</source>
            <translation>Co bylo provedeno</translation>
        </message>
        <message>
            <source>Outcome</source>
            <translation>Výsledek</translation>
        </message>
        <message>
            <source>Time (UTC)</source>
            <translation>Čas (UTC)</translation>
        </message>
        <message>
            <source>Type key</source>
            <translation>Typový klíč</translation>
        </message>
        <message>
            <source>Firmware</source>
            <translation>Firmware</translation>
        </message>
        <message>
            <source>User, station, link</source>
            <translation>Uživatel, stanice, připojení</translation>
        </message>
        <message>
            <source>Failed figures:</source>
            <translation>Nevyhovující hodnoty:</translation>
        </message>
        <message>
            <source>Open the PDF</source>
            <translation>Otevřít PDF</translation>
        </message>
        <message>
            <source>Compare with the record before</source>
            <translation>Porovnat s předchozím záznamem</translation>
        </message>
        <message>
            <source>Details:</source>
            <translation>Podrobnosti:</translation>
        </message>
        <message>
            <source>The PDF cannot be opened: {0}</source>
            <translation>PDF nelze otevřít: {0}</translation>
        </message>
    </context>
    <context>
        <name>ReportPage</name>
        <message>
            <source>Acceptance profile</source>
            <translation>Přejímací profil</translation>
        </message>
        <message>
            <source>steps of %1 %, a sine sweep of ±%2 % and a triangle over the whole range, about %3 s</source>
            <translation>skoky %1 %, rozmítaný sinus ±%2 % a trojúhelník přes celý rozsah, asi %3 s</translation>
        </message>
        <message>
            <source>Result: %1</source>
            <translation>Výsledek: %1</translation>
        </message>
        <message>
            <source>Limited by the link: %1</source>
            <translation>Omezeno spojením: %1</translation>
        </message>
        <message>
            <source>Save the test report</source>
            <translation>Uložit protokol o zkoušce</translation>
        </message>
        <message>
            <source>Cannot write the report: %1</source>
            <translation>Protokol nelze zapsat: %1</translation>
        </message>
        <message>
            <source>Acceptance profile (TOML, empty: default):</source>
            <translation>Přejímací profil (TOML, prázdné: výchozí):</translation>
        </message>
        <message>
            <source>Run the end-of-line test</source>
            <translation>Spustit výstupní zkoušku</translation>
        </message>
        <message>
            <source>Save PDF and CSV…</source>
            <translation>Uložit PDF a CSV…</translation>
        </message>
        <message>
            <source>Browse…</source>
            <translation>Procházet…</translation>
        </message>
        <message>
            <source>Figure</source>
            <translation>Ukazatel</translation>
        </message>
        <message>
            <source>Value</source>
            <translation>Hodnota</translation>
        </message>
        <message>
            <source>Limit</source>
            <translation>Mez</translation>
        </message>
        <message>
            <source>Result</source>
            <translation>Výsledek</translation>
        </message>
    </context>
    <context>
        <name>RestartDialog</name>
        <message>
            <source>Restart valve</source>
            <translation>Restart ventilu</translation>
        </message>
        <message>
            <source>Restore factory values</source>
            <translation>Obnovit tovární nastavení</translation>
        </message>
        <message>
            <source>Verify by restart</source>
            <translation>Ověřit restartem</translation>
        </message>
        <message>
            <source>Restore and restart</source>
            <translation>Obnovit a restartovat</translation>
        </message>
        <message>
            <source>Restart and verify</source>
            <translation>Restartovat a ověřit</translation>
        </message>
        <message>
            <source>&lt;b&gt;Restarting the valve electronics is only allowed with the hydraulic circuit disconnected.&lt;/b&gt;&lt;br&gt;During the restart the spool returns to its spring-centred position and the setpoint is ignored for a few seconds.</source>
            <translation>&lt;b&gt;Restart elektroniky ventilu je dovolen pouze při odpojeném hydraulickém obvodu.&lt;/b&gt;&lt;br&gt;Během restartu se šoupátko vrátí působením středicích pružin do střední polohy a žádaná hodnota je několik sekund ignorována.</translation>
        </message>
        <message>
            <source>The valve's stored parameters are reset to the factory values, which take effect after a restart of the valve. Before that, the valve's parameters are saved to a backup file (if this valve has no backup yet).</source>
            <translation>Uložené parametry ventilu se vrátí na tovární hodnoty, které začnou platit po restartu ventilu. Předtím se parametry ventilu uloží do záložního souboru (pokud pro tento ventil ještě žádná záloha není).</translation>
        </message>
        <message>
            <source>The hydraulics are disconnected</source>
            <translation>Hydraulický obvod je odpojen</translation>
        </message>
        <message>
            <source>Restart</source>
            <translation>Restartovat</translation>
        </message>
    </context>
    <context>
        <name>RestartVerifier</name>
        <message>
            <source>Verify by restart</source>
            <translation>Ověřit restartem</translation>
        </message>
        <message>
            <source>Upload the parameters to the valve first: the verification restarts the valve and reads back whether it kept the last upload.</source>
            <translation>Nejprve načtěte parametry do ventilu: ověření ventil restartuje a zpětně načte, zda si ponechal naposledy načtené hodnoty.</translation>
        </message>
        <message>
            <source>The valve works with values changed online since the upload that it has not stored: a restart would lose them. Store them first (Valve → Store in valve), then verify. The valve was not restarted.</source>
            <translation>Ventil pracuje s hodnotami změněnými online od načtení do ventilu, které neuložil: restart by je ztratil. Nejprve je uložte (Ventil → Uložit do paměti ventilu), pak ověřte. Ventil nebyl restartován.</translation>
        </message>
        <message numerus="yes">
            <source>The last upload wrote %n parameter(s): {0}. The valve is restarted, then its parameters are read back and compared with the document: this shows that it keeps them through a restart, as after a power loss.</source>
            <translation>
                <numerusform>Poslední načtení do ventilu zapsalo %n parametr: {0}. Ventil se restartuje, pak se jeho parametry zpětně načtou a porovnají s dokumentem: to ukáže, že si je ponechá i po restartu, jako po výpadku napájení.</numerusform>
                <numerusform>Poslední načtení do ventilu zapsalo %n parametry: {0}. Ventil se restartuje, pak se jeho parametry zpětně načtou a porovnají s dokumentem: to ukáže, že si je ponechá i po restartu, jako po výpadku napájení.</numerusform>
                <numerusform>Poslední načtení do ventilu zapsalo %n parametrů: {0}. Ventil se restartuje, pak se jeho parametry zpětně načtou a porovnají s dokumentem: to ukáže, že si je ponechá i po restartu, jako po výpadku napájení.</numerusform>
            </translation>
        </message>
        <message>
            <source>Verification by restart cancelled: the valve was not restarted</source>
            <translation>Ověření restartem zrušeno: ventil nebyl restartován</translation>
        </message>
        <message>
            <source>Restarting the valve and reading its parameters back…</source>
            <translation>Ventil se restartuje a jeho parametry se zpětně načítají…</translation>
        </message>
        <message>
            <source>stored with its store command</source>
            <translation>uloženo jeho příkazem k uložení</translation>
        </message>
        <message numerus="yes">
            <source>%n parameter(s) of the last upload read back unchanged at {0}: {1}</source>
            <translation>
                <numerusform>%n parametr posledního načtení do ventilu zpětně načten beze změny v {0}: {1}</numerusform>
                <numerusform>%n parametry posledního načtení do ventilu zpětně načteny beze změny v {0}: {1}</numerusform>
                <numerusform>%n parametrů posledního načtení do ventilu zpětně načteno beze změny v {0}: {1}</numerusform>
            </translation>
        </message>
        <message>
            <source>Verification by restart failed: the valve did not keep {0}</source>
            <translation>Ověření restartem selhalo: ventil si neponechal {0}</translation>
        </message>
        <message numerus="yes">
            <source>After the restart the valve reads back %n value(s) of the last upload otherwise: it did not keep them ({0}). It works with the values read back now (expected → read back below); the document still holds the uploaded values and the history records the differences. Edits no longer go to the valve: upload the document again, or download the valve's values.</source>
            <translation>
                <numerusform>Po restartu ventil zpětně načítá %n hodnotu posledního načtení do ventilu jinak: neponechal si ji ({0}). Pracuje s hodnotou načtenou nyní (očekáváno → načteno níže); dokument dál obsahuje načtenou hodnotu a historie zaznamenává rozdíl. Změny už nejdou do ventilu: načtěte dokument do ventilu znovu, nebo stáhněte hodnoty z ventilu.</numerusform>
                <numerusform>Po restartu ventil zpětně načítá %n hodnoty posledního načtení do ventilu jinak: neponechal si je ({0}). Pracuje s hodnotami načtenými nyní (očekáváno → načteno níže); dokument dál obsahuje načtené hodnoty a historie zaznamenává rozdíly. Změny už nejdou do ventilu: načtěte dokument do ventilu znovu, nebo stáhněte hodnoty z ventilu.</numerusform>
                <numerusform>Po restartu ventil zpětně načítá %n hodnot posledního načtení do ventilu jinak: neponechal si je ({0}). Pracuje s hodnotami načtenými nyní (očekáváno → načteno níže); dokument dál obsahuje načtené hodnoty a historie zaznamenává rozdíly. Změny už nejdou do ventilu: načtěte dokument do ventilu znovu, nebo stáhněte hodnoty z ventilu.</numerusform>
            </translation>
        </message>
        <message>
            <source>The valve did not come back after the restart</source>
            <translation>Ventil se po restartu znovu neozval</translation>
        </message>
        <message>
            <source>Check the valve's supply and cable, then go online again: prm9tool compares the valve with the document.</source>
            <translation>Zkontrolujte napájení a kabel ventilu a pak znovu přejděte do režimu online: prm9tool porovná ventil s dokumentem.</translation>
        </message>
        <message>
            <source>prm9tool looks for the valve; when it is back, prm9tool compares it with the document and you decide what to do.</source>
            <translation>prm9tool ventil hledá; až bude zpět, prm9tool ho porovná s dokumentem a vy rozhodnete, co dál.</translation>
        </message>
        <message>
            <source>The valve did not come back after the restart; prm9tool is offline now.
As far as known, the valve holds the values of the last upload ({0}): every one read back correctly before the restart, but whether it kept them through the restart could not be read.
Nothing was lost on the PC side: the document still holds every value, the backup and the history are unchanged. {1}</source>
            <translation>Ventil se po restartu znovu neozval; prm9tool je nyní offline.
Pokud je známo, ventil obsahuje naposledy načtené hodnoty ({0}): každá se před restartem zpětně načetla správně, zda si je ale ponechal i po restartu, se načíst nepodařilo.
Na straně PC se nic neztratilo: dokument dál obsahuje každou hodnotu, záloha a historie jsou beze změny. {1}</translation>
        </message>
    </context>
    <context>
        <name>ScopeDisplay</name>
        <message>
            <source>the samples between cursors A and B</source>
            <translation>vzorky mezi kurzory A a B</translation>
        </message>
        <message>
            <source>the visible window</source>
            <translation>viditelné okno</translation>
        </message>
    </context>
    <context>
        <name>ScopeExport</name>
        <message>
            <source>Nothing recorded yet.</source>
            <translation>Zatím nic nezaznamenáno.</translation>
        </message>
        <message>
            <source>Could not write {0}.</source>
            <translation>{0} nelze zapsat.</translation>
        </message>
        <message>
            <source>Export CSV</source>
            <translation>Export CSV</translation>
        </message>
        <message>
            <source>CSV files (*.csv)</source>
            <translation>Soubory CSV (*.csv)</translation>
        </message>
        <message>
            <source>Export PNG</source>
            <translation>Export PNG</translation>
        </message>
        <message>
            <source>PNG images (*.png)</source>
            <translation>Obrázky PNG (*.png)</translation>
        </message>
        <message>
            <source>Export</source>
            <translation>Export</translation>
        </message>
        <message>
            <source>Saved {0}.</source>
            <translation>Uloženo: {0}.</translation>
        </message>
    </context>
    <context>
        <name>ScopePlot</name>
        <message>
            <source>Auto</source>
            <translation>Auto</translation>
        </message>
        <message>
            <source>Scale this channel to its data again</source>
            <translation>Znovu přizpůsobit měřítko kanálu jeho datům</translation>
        </message>
        <message>
            <source>at stop:</source>
            <translation>při zastavení:</translation>
        </message>
        <message>
            <source>The last value recorded before Stop; the valve may hold another now.</source>
            <translation>Poslední hodnota zaznamenaná před zastavením; ventil už může mít jinou.</translation>
        </message>
        <message>
            <source>Time from trigger [ms]</source>
            <translation>Čas od spuštění [ms]</translation>
        </message>
        <message>
            <source>Time from trigger [s]</source>
            <translation>Čas od spuštění [s]</translation>
        </message>
        <message>
            <source>Time [ms]</source>
            <translation>Čas [ms]</translation>
        </message>
        <message>
            <source>Time [s]</source>
            <translation>Čas [s]</translation>
        </message>
        <message>
            <source>The valve's newest value. The plot holds an earlier recording; read it with the cursors.</source>
            <translation>Nejnovější hodnota ventilu. Graf drží dřívější záznam; odečtěte jej kurzory.</translation>
        </message>
        <message>
            <source>live:</source>
            <translation>aktuálně:</translation>
        </message>
    </context>
    <context>
        <name>ScopeStatusText</name>
        <message>
            <source>The valve does not follow its setpoint: {0}</source>
            <translation>Ventil nesleduje svou žádanou hodnotu: {0}</translation>
        </message>
        <message>
            <source>Stopped. Choose up to three measuring points and press Start.</source>
            <translation>Zastaveno. Zvolte až tři měřicí body a stiskněte Start.</translation>
        </message>
        <message>
            <source>Single capture complete. Resume arms the trigger again.</source>
            <translation>Jednorázový záznam dokončen. Tlačítko Pokračovat znovu aktivuje spouštění.</translation>
        </message>
        <message>
            <source>Paused: zoom and pan with the mouse; recording continues.</source>
            <translation>Pozastaveno: přibližujte a posouvejte myší; záznam pokračuje.</translation>
        </message>
        <message>
            <source>Waiting for the trigger…</source>
            <translation>Čekání na spouštění…</translation>
        </message>
        <message>
            <source>Recording at {0} Hz.</source>
            <translation>Záznam se vzorkovací frekvencí {0} Hz.</translation>
        </message>
        <message>
            <source>Recording at {0} Hz of the {1} Hz asked for: {2} samples lost on the link.</source>
            <translation>Záznam s frekvencí {0} Hz z požadovaných {1} Hz: na spojení ztraceno vzorků: {2}.</translation>
        </message>
        <message>
            <source>The oscilloscope needs a connected valve: go online (Communication → Online).</source>
            <translation>Osciloskop potřebuje připojený ventil: přejděte do režimu online (Komunikace → Režim online).</translation>
        </message>
        <message>
            <source>The recording stopped: another operation (a tuning test…) took the stream.</source>
            <translation>Záznam se zastavil: datový tok převzala jiná operace (test ladění…).</translation>
        </message>
        <message>
            <source>The recording stopped: {0}</source>
            <translation>Záznam se zastavil: {0}</translation>
        </message>
        <message>
            <source>The link dropped: the setpoint generator has stopped.</source>
            <translation>Spojení se přerušilo: generátor žádané hodnoty se zastavil.</translation>
        </message>
        <message>
            <source>The setpoint generator has stopped: another operation (a tuning test, an upload…) drives the valve now.</source>
            <translation>Generátor žádané hodnoty se zastavil: ventil nyní řídí jiná operace (test ladění, načtení do ventilu…).</translation>
        </message>
        <message>
            <source>The valve refused a value of the setpoint generator ({0}): the generator has stopped.</source>
            <translation>Ventil odmítl hodnotu generátoru žádané hodnoty ({0}): generátor se zastavil.</translation>
        </message>
        <message>
            <source>no reason given</source>
            <translation>bez udání důvodu</translation>
        </message>
    </context>
    <context>
        <name>ScopeWidget</name>
        <message>
            <source>Select at least one measuring point on the right.</source>
            <translation>Vpravo zvolte alespoň jeden měřicí bod.</translation>
        </message>
        <message>
            <source>The recording could not start: {0}</source>
            <translation>Záznam nelze spustit: {0}</translation>
        </message>
        <message>
            <source>Tuning and characterization…</source>
            <translation>Ladění a charakterizace…</translation>
        </message>
    </context>
    <context>
        <name>SensorScalingDialog</name>
        <message>
            <source>Sensor signal in (%)</source>
            <translation>Signál snímače na vstupu (%)</translation>
        </message>
        <message>
            <source>Process actual value (%)</source>
            <translation>Skutečná procesní veličina (%)</translation>
        </message>
        <message>
            <source>1:1</source>
            <translation>1:1</translation>
        </message>
        <message>
            <source>after offset and gain</source>
            <translation>za posunutím a zesílením</translation>
        </message>
    </context>
    <context>
        <name>Service</name>
        <message>
            <source>the setpoint generator</source>
            <translation>generátor žádané hodnoty</translation>
        </message>
        <message>
            <source>the capture with a stimulus</source>
            <translation>záznam s buzením</translation>
        </message>
        <message>
            <source>the tuning test</source>
            <translation>test ladění</translation>
        </message>
        <message>
            <source>the characterization</source>
            <translation>charakterizace</translation>
        </message>
        <message>
            <source>the autotune</source>
            <translation>Autotune</translation>
        </message>
        <message>
            <source>the field signature</source>
            <translation>polní podpis</translation>
        </message>
        <message>
            <source>{0} cannot start while {1} runs on this valve: stop {1} first; nothing was started</source>
            <translation>{0} nemůže začít, dokud na tomto ventilu běží {1}: nejprve zastavte {1}; nic nebylo spuštěno</translation>
        </message>
        <message>
            <source>{0}: expected a number in {1}, got {2}</source>
            <translation>{0}: očekáváno číslo v {1}, ne {2}</translation>
        </message>
        <message>
            <source>{0}: the parameter is read-only</source>
            <translation>{0}: parametr je pouze pro čtení</translation>
        </message>
    </context>
    <context>
        <name>SetpointGenerator</name>
        <message>
            <source>The setpoint generator needs a connected valve.</source>
            <translation>Generátor žádané hodnoty potřebuje připojený ventil.</translation>
        </message>
        <message>
            <source>The valve is busy with another operation; start the generator after it.</source>
            <translation>Ventil provádí jinou operaci; spusťte generátor až po ní.</translation>
        </message>
    </context>
    <context>
        <name>SignalInputDialog</name>
        <message>
            <source>%1 — recommended</source>
            <translation>%1 – doporučeno</translation>
        </message>
        <message>
            <source>Recommended for this coil layout (manual table 8-4) are the types marked 'recommended'. With positive polarity a positive setpoint drives coil A.</source>
            <translation>Pro toto uspořádání cívek (příručka, tabulka 8-4) jsou doporučeny typy označené „doporučeno“. Při kladné polaritě kladná žádaná hodnota napájí cívku A.</translation>
        </message>
        <message>
            <source>With inverted polarity the sensor signal enters the process loop with a negative sign.</source>
            <translation>Při obrácené polaritě vstupuje signál snímače do regulační smyčky se záporným znaménkem.</translation>
        </message>
        <message>
            <source>Input signal (%1)</source>
            <translation>Vstupní signál (%1)</translation>
        </message>
        <message>
            <source>Internal value (%)</source>
            <translation>Interní hodnota (%)</translation>
        </message>
        <message>
            <source>internal value</source>
            <translation>interní hodnota</translation>
        </message>
        <message>
            <source>This type is not recommended for a valve with %1 (manual table 8-4).</source>
            <translation>Tento typ se pro ventil s %1 nedoporučuje (příručka, tabulka 8-4).</translation>
        </message>
    </context>
    <context>
        <name>SignaturePage</name>
        <message>
            <source>The birth certificate is compared with the valve itself: go online with the valve first.</source>
            <translation>Rodný list se porovnává se samotným ventilem: nejprve se s ventilem připojte online.</translation>
        </message>
        <message>
            <source>a small and a large step each way, a short sine sweep and a hysteresis loop, at most %1 s</source>
            <translation>malý a velký skok v obou směrech, krátký sinusový rozmítaný signál a hysterezní smyčka, nejvýše %1 s</translation>
        </message>
        <message>
            <source>Not compared: %1</source>
            <translation>Neporovnáno: %1</translation>
        </message>
        <message>
            <source>Save the drift report</source>
            <translation>Uložit protokol o driftu</translation>
        </message>
        <message>
            <source>Cannot write the report: %1</source>
            <translation>Protokol nelze zapsat: %1</translation>
        </message>
        <message>
            <source>A short field signature of the valve, compared with its birth certificate: the end-of-line test kept in the history for its serial. Each figure is judged against the drift limits of the acceptance profile chosen on the Test report page ([drift]; empty: the defaults).</source>
            <translation>Krátký polní podpis ventilu porovnaný s jeho rodným listem: výstupní zkouškou uloženou v historii k jeho výrobnímu číslu. Každý ukazatel se posuzuje podle mezí driftu přejímacího profilu zvoleného na stránce Protokol o zkoušce ([drift]; prázdné: výchozí).</translation>
        </message>
        <message>
            <source>Compare with birth certificate</source>
            <translation>Porovnat s rodným listem</translation>
        </message>
        <message>
            <source>Save PDF…</source>
            <translation>Uložit PDF…</translation>
        </message>
    </context>
    <context>
        <name>SignatureReport</name>
        <message>
            <source>not reached</source>
            <translation>nedosaženo</translation>
        </message>
        <message>
            <source>above %1</source>
            <translation>nad %1</translation>
        </message>
        <message>
            <source>pp</source>
            <translation>p. b.</translation>
        </message>
        <message>
            <source>not judged</source>
            <translation>neposouzeno</translation>
        </message>
        <message>
            <source>DRIFTED</source>
            <translation>DRIFT</translation>
        </message>
        <message>
            <source>within</source>
            <translation>v mezích</translation>
        </message>
        <message>
            <source>the end-of-line test on %1</source>
            <translation>výstupní zkoušky %1</translation>
        </message>
        <message>
            <source>the first characterization on %1</source>
            <translation>první charakterizace %1</translation>
        </message>
        <message>
            <source>No figure drifted beyond its limit since %1.</source>
            <translation>Od %1 žádný ukazatel nepřekročil svou mez driftu.</translation>
        </message>
        <message>
            <source>%1 %2, was %3</source>
            <translation>%1 %2, bylo %3</translation>
        </message>
        <message>
            <source>Drifted since %1: %2.</source>
            <translation>Drift od %1: %2.</translation>
        </message>
        <message>
            <source>Figure</source>
            <translation>Ukazatel</translation>
        </message>
        <message>
            <source>Today</source>
            <translation>Dnes</translation>
        </message>
        <message>
            <source>Birth certificate</source>
            <translation>Rodný list</translation>
        </message>
        <message>
            <source>Change</source>
            <translation>Změna</translation>
        </message>
        <message>
            <source>Drift limit</source>
            <translation>Mez driftu</translation>
        </message>
        <message>
            <source>Result</source>
            <translation>Výsledek</translation>
        </message>
        <message>
            <source>birth certificate</source>
            <translation>rodný list</translation>
        </message>
        <message>
            <source>today, step down ×−1</source>
            <translation>dnes, skok dolů ×−1</translation>
        </message>
        <message>
            <source>setpoint</source>
            <translation>žádaná hodnota</translation>
        </message>
        <message>
            <source>today</source>
            <translation>dnes</translation>
        </message>
        <message>
            <source>Step response ±%1 %</source>
            <translation>Přechodová charakteristika ±%1 %</translation>
        </message>
        <message>
            <source>time [ms]</source>
            <translation>čas [ms]</translation>
        </message>
        <message>
            <source>frequency [Hz]</source>
            <translation>frekvence [Hz]</translation>
        </message>
        <message>
            <source>Frequency response: magnitude</source>
            <translation>Frekvenční charakteristika: amplituda</translation>
        </message>
        <message>
            <source>Frequency response: phase</source>
            <translation>Frekvenční charakteristika: fáze</translation>
        </message>
        <message>
            <source>The birth certificate's record keeps its figures but not its curves (recorded by an older prm9tool): the plots show today's only.</source>
            <translation>Záznam rodného listu obsahuje jeho ukazatele, ale ne křivky (zaznamenal jej starší prm9tool): grafy ukazují jen dnešní.</translation>
        </message>
        <message>
            <source>Type key</source>
            <translation>Objednací kód</translation>
        </message>
        <message>
            <source>Serial number</source>
            <translation>Výrobní číslo</translation>
        </message>
        <message>
            <source>Firmware</source>
            <translation>Firmware</translation>
        </message>
        <message>
            <source>Date</source>
            <translation>Datum</translation>
        </message>
        <message>
            <source>Link</source>
            <translation>Spojení</translation>
        </message>
        <message>
            <source>Loop tested</source>
            <translation>Zkoušená regulační smyčka</translation>
        </message>
        <message>
            <source>Drift limits</source>
            <translation>Meze driftu</translation>
        </message>
        <message>
            <source>Motion</source>
            <translation>Pohyb</translation>
        </message>
        <message>
            <source>no drift</source>
            <translation>bez driftu</translation>
        </message>
        <message>
            <source>Limited by the link</source>
            <translation>Omezeno spojením</translation>
        </message>
        <message>
            <source>PRM9 field signature and drift report</source>
            <translation>Polní podpis a protokol o driftu PRM9</translation>
        </message>
        <message>
            <source>{0} · serial number {1}</source>
            <translation>{0} · výrobní číslo {1}</translation>
        </message>
        <message>
            <source>PRM9 drift report</source>
            <translation>Protokol o driftu PRM9</translation>
        </message>
    </context>
    <context>
        <name>StaticPage</name>
        <message>
            <source>a triangle over the whole range −100 … 100 %, %1 s</source>
            <translation>trojúhelník přes celý rozsah −100 … 100 %, %1 s</translation>
        </message>
        <message>
            <source>Gain %1, hysteresis %2 %, linearity error %3 %, dead band %4 %.</source>
            <translation>Zesílení %1, hystereze %2 %, chyba linearity %3 %, pásmo necitlivosti %4 %.</translation>
        </message>
        <message>
            <source>Triangle period:</source>
            <translation>Perioda trojúhelníku:</translation>
        </message>
        <message>
            <source>Measure the static characteristic</source>
            <translation>Změřit statickou charakteristiku</translation>
        </message>
        <message>
            <source>No proposal: this link does not sample the setpoint chain (USB and the emulator do).</source>
            <translation>Žádný návrh: toto spojení nevzorkuje řetězec řídicího signálu (USB a emulátor ano).</translation>
        </message>
        <message>
            <source>Dead band behind the gain/offset stage %1 … %2 %: offsets %3.</source>
            <translation>Pásmo necitlivosti za stupněm zesílení/posunutí nuly %1 … %2 %: posunutí nuly %3.</translation>
        </message>
        <message>
            <source>with the proposed offsets and linearization (preview)</source>
            <translation>s navrženým posunutím nuly a linearizací (náhled)</translation>
        </message>
        <message>
            <source>Offsets and linearization from the static characteristic</source>
            <translation>Posunutí nuly a linearizace ze statické charakteristiky</translation>
        </message>
        <message>
            <source>Apply the proposed offsets and linearization</source>
            <translation>Použít navržené posunutí nuly a linearizaci</translation>
        </message>
    </context>
    <context>
        <name>StepFigures</name>
        <message>
            <source>did not settle within ±{0} % of the step: oscillation of {1} at {2} Hz</source>
            <translation>neustálilo se v pásmu ±{0} % skoku: kmitání {1} při {2} Hz</translation>
        </message>
        <message>
            <source>did not settle within ±{0} % of the step: still moving by {1} at the end</source>
            <translation>neustálilo se v pásmu ±{0} % skoku: na konci se ještě mění o {1}</translation>
        </message>
        <message>
            <source>Step {0} → {1} %, window {2} … {3} ms</source>
            <translation>Skok {0} → {1} %, okno {2} … {3} ms</translation>
        </message>
        <message>
            <source>not reached: the response ended at {0} of the setpoint {1}</source>
            <translation>nedosaženo: odezva skončila na {0} z žádané hodnoty {1}</translation>
        </message>
    </context>
    <context>
        <name>StepPanel</name>
        <message>
            <source>Step response</source>
            <translation>Přechodová charakteristika</translation>
        </message>
        <message>
            <source>Only between cursors A and B</source>
            <translation>Jen mezi kurzory A a B</translation>
        </message>
        <message>
            <source>Reference</source>
            <translation>Reference</translation>
        </message>
        <message>
            <source>Response</source>
            <translation>Odezva</translation>
        </message>
        <message>
            <source>Step</source>
            <translation>Skok</translation>
        </message>
        <message>
            <source>Rise time 10–90 %</source>
            <translation>Doba náběhu 10–90 %</translation>
        </message>
        <message>
            <source>Overshoot</source>
            <translation>Překmit</translation>
        </message>
        <message>
            <source>Settling time ±2 %</source>
            <translation>Doba ustálení ±2 %</translation>
        </message>
        <message>
            <source>Steady-state error</source>
            <translation>Trvalá regulační odchylka</translation>
        </message>
        <message>
            <source>(none: step on the response)</source>
            <translation>(žádná: skok na odezvě)</translation>
        </message>
        <message>
            <source>No step found: the reference channel has no data in {0}. Over CANopen the valve does not report its demand value; the channel shows the setpoint prm9tool sends while its setpoint generator runs. Start the generator, or choose “(none: step on the response)”.</source>
            <translation>Skok nenalezen: referenční kanál nemá v {0} žádná data. Přes CANopen ventil svou žádanou hodnotu nehlásí; kanál ukazuje žádanou hodnotu, kterou prm9tool posílá, dokud běží jeho generátor žádané hodnoty. Spusťte generátor, nebo zvolte „(žádná: skok na odezvě)“.</translation>
        </message>
        <message>
            <source>No step found: the response channel has no data in {0} (the link does not deliver this measuring point, or lost every sample).</source>
            <translation>Skok nenalezen: kanál odezvy nemá v {0} žádná data (spojení tento měřicí bod nedodává, nebo ztratilo všechny vzorky).</translation>
        </message>
        <message>
            <source>No step found in {0}.</source>
            <translation>V {0} nebyl nalezen žádný skok.</translation>
        </message>
        <message>
            <source>Measured on {0}.</source>
            <translation>Měřeno na {0}.</translation>
        </message>
        <message>
            <source>No response to the step in {0}: the response stays flat or within its noise.</source>
            <translation>Žádná odezva na skok v {0}: odezva zůstává plochá nebo v rámci šumu.</translation>
        </message>
        <message>
            <source>Measured on step {0} of {1} in {2}.</source>
            <translation>Změřeno na skoku {0} z {1} v {2}.</translation>
        </message>
        <message>
            <source>Window too short: in {0} the response has not come to rest yet. Widen the time window or move the cursors apart.</source>
            <translation>Okno je příliš krátké: v {0} se odezva ještě neustálila. Zvětšete časové okno nebo oddalte kurzory.</translation>
        </message>
    </context>
    <context>
        <name>StepResponse</name>
        <message>
            <source>not reached</source>
            <translation>nedosaženo</translation>
        </message>
        <message>
            <source>{0}: overshoot {1} %, rise time {2}, settling (±2 %) {3}, remaining error {4} %</source>
            <translation>{0}: překmit {1} %, doba náběhu {2}, ustálení (±2 %) {3}, zbývající odchylka {4} %</translation>
        </message>
    </context>
    <context>
        <name>ThresholdGainDialog</name>
        <message>
            <source>Control deviation in (%)</source>
            <translation>Regulační odchylka na vstupu (%)</translation>
        </message>
        <message>
            <source>Setpoint in (%)</source>
            <translation>Žádaná hodnota na vstupu (%)</translation>
        </message>
        <message>
            <source>Control deviation out (%)</source>
            <translation>Regulační odchylka na výstupu (%)</translation>
        </message>
        <message>
            <source>Setpoint out (%)</source>
            <translation>Žádaná hodnota na výstupu (%)</translation>
        </message>
        <message>
            <source>1:1</source>
            <translation>1:1</translation>
        </message>
        <message>
            <source>output</source>
            <translation>výstup</translation>
        </message>
    </context>
    <context>
        <name>TraceWindow</name>
        <message>
            <source>CAN trace</source>
            <translation>Záznam CAN</translation>
        </message>
        <message>
            <source>Open trace…</source>
            <translation>Otevřít záznam…</translation>
        </message>
        <message>
            <source>Open a trace file (ASC, BLF, TRC or candump log).</source>
            <translation>Otevřete soubor záznamu (ASC, BLF, TRC nebo candump log).</translation>
        </message>
        <message>
            <source>Time (s)</source>
            <translation>Čas (s)</translation>
        </message>
        <message>
            <source>Node</source>
            <translation>Uzel</translation>
        </message>
        <message>
            <source>Kind</source>
            <translation>Druh</translation>
        </message>
        <message>
            <source>Decoding {0}…</source>
            <translation>Dekóduje se {0}…</translation>
        </message>
        <message>
            <source>Open a CAN trace</source>
            <translation>Otevřít záznam CAN</translation>
        </message>
        <message>
            <source>CAN traces ({0})</source>
            <translation>Záznamy CAN ({0})</translation>
        </message>
        <message>
            <source>The trace cannot be read: {0}</source>
            <translation>Záznam nelze přečíst: {0}</translation>
        </message>
        <message>
            <source>{0}: {1} frames, {2} events, {3} not understood, {4} incidents</source>
            <translation>{0}: {1} rámců, {2} událostí, {3} nesrozumitelných, {4} incidentů</translation>
        </message>
        <message>
            <source>; SYNC period {0:.3f} ms, jitter {1:.1f} µs</source>
            <translation>; perioda SYNC {0:.3f} ms, jitter {1:.1f} µs</translation>
        </message>
        <message>
            <source>every node</source>
            <translation>každý uzel</translation>
        </message>
        <message>
            <source>the whole bus</source>
            <translation>celá sběrnice</translation>
        </message>
        <message>
            <source>node {0}</source>
            <translation>uzel {0}</translation>
        </message>
        <message>
            <source>every kind</source>
            <translation>každý druh</translation>
        </message>
        <message>
            <source>node {0}: {1}</source>
            <translation>uzel {0}: {1}</translation>
        </message>
    </context>
    <context>
        <name>TuningReport</name>
        <message>
            <source>overshoot</source>
            <translation>překmit</translation>
        </message>
        <message>
            <source>rise time (10–90 %)</source>
            <translation>doba náběhu (10–90 %)</translation>
        </message>
        <message>
            <source>settling time (±2 %)</source>
            <translation>doba ustálení (±2 %)</translation>
        </message>
        <message>
            <source>−3 dB frequency</source>
            <translation>frekvence −3 dB</translation>
        </message>
        <message>
            <source>−90° frequency</source>
            <translation>frekvence −90°</translation>
        </message>
        <message>
            <source>gain</source>
            <translation>zesílení</translation>
        </message>
        <message>
            <source>hysteresis</source>
            <translation>hystereze</translation>
        </message>
        <message>
            <source>linearity error</source>
            <translation>chyba linearity</translation>
        </message>
        <message>
            <source>dead band</source>
            <translation>pásmo necitlivosti</translation>
        </message>
        <message>
            <source>step %1 → %2 %: %3</source>
            <translation>skok %1 → %2 %: %3</translation>
        </message>
        <message>
            <source>step %1 %: %2</source>
            <translation>skok %1 %: %2</translation>
        </message>
        <message>
            <source>process controller (E04): process actual value</source>
            <translation>procesní regulátor (E04): skutečná hodnota procesu</translation>
        </message>
        <message>
            <source>position controller: spool position</source>
            <translation>polohový regulátor: poloha šoupátka</translation>
        </message>
        <message>
            <source>emulator (stepped faster than real time)</source>
            <translation>emulátor (počítaný rychleji než v reálném čase)</translation>
        </message>
        <message>
            <source>TPDO1 at the tool's SYNC</source>
            <translation>TPDO1 při SYNC programu</translation>
        </message>
        <message>
            <source>SDO polling</source>
            <translation>dotazování SDO</translation>
        </message>
        <message>
            <source>CANopen node {0} ({1}), {2}, one sample per {3} ms</source>
            <translation>uzel CANopen {0} ({1}), {2}, jeden vzorek za {3} ms</translation>
        </message>
        <message>
            <source>default (built in)</source>
            <translation>výchozí (vestavěný)</translation>
        </message>
        <message>
            <source>PASS</source>
            <translation>VYHOVUJE</translation>
        </message>
        <message>
            <source>FAIL</source>
            <translation>NEVYHOVUJE</translation>
        </message>
        <message>
            <source>not reached</source>
            <translation>nedosaženo</translation>
        </message>
        <message>
            <source>above {0}</source>
            <translation>nad {0}</translation>
        </message>
        <message>
            <source>Step response %1 %</source>
            <translation>Přechodová charakteristika %1 %</translation>
        </message>
        <message>
            <source>time [ms]</source>
            <translation>čas [ms]</translation>
        </message>
        <message>
            <source>setpoint</source>
            <translation>žádaná hodnota</translation>
        </message>
        <message>
            <source>actual</source>
            <translation>skutečná hodnota</translation>
        </message>
        <message>
            <source>frequency [Hz]</source>
            <translation>frekvence [Hz]</translation>
        </message>
        <message>
            <source>Frequency response ±%1 %: magnitude</source>
            <translation>Frekvenční charakteristika ±%1 %: amplituda</translation>
        </message>
        <message>
            <source>magnitude</source>
            <translation>amplituda</translation>
        </message>
        <message>
            <source>Phase and coherence</source>
            <translation>Fáze a koherence</translation>
        </message>
        <message>
            <source>phase</source>
            <translation>fáze</translation>
        </message>
        <message>
            <source>coherence ×100</source>
            <translation>koherence ×100</translation>
        </message>
        <message>
            <source>Static characteristic</source>
            <translation>Statická charakteristika</translation>
        </message>
        <message>
            <source>demand [%]</source>
            <translation>žádaná hodnota [%]</translation>
        </message>
        <message>
            <source>actual [%]</source>
            <translation>skutečná hodnota [%]</translation>
        </message>
        <message>
            <source>rising</source>
            <translation>stoupající</translation>
        </message>
        <message>
            <source>falling</source>
            <translation>klesající</translation>
        </message>
        <message>
            <source>best line</source>
            <translation>proložená přímka</translation>
        </message>
        <message>
            <source>{0} · serial number {1}</source>
            <translation>{0} · výrobní číslo {1}</translation>
        </message>
        <message>
            <source>Type key</source>
            <translation>Objednací kód</translation>
        </message>
        <message>
            <source>Serial number</source>
            <translation>Sériové číslo</translation>
        </message>
        <message>
            <source>Firmware</source>
            <translation>Firmware</translation>
        </message>
        <message>
            <source>Date</source>
            <translation>Datum</translation>
        </message>
        <message>
            <source>Link</source>
            <translation>Spojení</translation>
        </message>
        <message>
            <source>Loop tested</source>
            <translation>Zkoušená regulační smyčka</translation>
        </message>
        <message>
            <source>Acceptance profile</source>
            <translation>Přejímací profil</translation>
        </message>
        <message>
            <source>Result</source>
            <translation>Výsledek</translation>
        </message>
        <message>
            <source>Limited by the link</source>
            <translation>Omezeno spojením</translation>
        </message>
        <message>
            <source>Figures</source>
            <translation>Hodnoty</translation>
        </message>
        <message>
            <source>Parameter set</source>
            <translation>Sada parametrů</translation>
        </message>
        <message>
            <source>PRM9 test report</source>
            <translation>Protokol o zkoušce PRM9</translation>
        </message>
        <message>
            <source>Figure</source>
            <translation>Ukazatel</translation>
        </message>
        <message>
            <source>Value</source>
            <translation>Hodnota</translation>
        </message>
        <message>
            <source>Limit</source>
            <translation>Mez</translation>
        </message>
        <message>
            <source>flow characteristic: %1</source>
            <translation>průtoková charakteristika: %1</translation>
        </message>
        <message>
            <source>Flow characteristic</source>
            <translation>Průtoková charakteristika</translation>
        </message>
        <message>
            <source>spool opening [%]</source>
            <translation>otevření šoupátka [%]</translation>
        </message>
        <message>
            <source>actuator velocity [%/s]</source>
            <translation>rychlost pohonu [%/s]</translation>
        </message>
        <message>
            <source>measured</source>
            <translation>změřeno</translation>
        </message>
    </context>
    <context>
        <name>TuningRunner</name>
        <message>
            <source>The valve is back: what the broken test had changed is restored ({0}) and the setpoint is the valve's own again.</source>
            <translation>Ventil je zpět: co přerušený test změnil, je obnoveno ({0}) a žádaná hodnota je opět vlastní hodnotou ventilu.</translation>
        </message>
    </context>
    <context>
        <name>TuningWindow</name>
        <message>
            <source>Running: %1</source>
            <translation>Probíhá: %1</translation>
        </message>
        <message>
            <source>This test moves the spool (and on E04 the actuator): %1.

Make sure the hydraulics are safe for it. Stop ends it at any time and puts the valve back as it was. Start the test?</source>
            <translation>Tento test pohybuje šoupátkem (a u E04 pohonem): %1.

Zajistěte, aby to hydraulika bezpečně snesla. Tlačítko Stop test kdykoli ukončí a vrátí ventil do původního stavu. Spustit test?</translation>
        </message>
        <message>
            <source>Tuning</source>
            <translation>Ladění</translation>
        </message>
        <message>
            <source>The oscilloscope's setpoint generator was stopped for the test.</source>
            <translation>Generátor žádané hodnoty osciloskopu byl kvůli zkoušce zastaven.</translation>
        </message>
        <message>
            <source>Not started: the valve does not follow its setpoint: %1</source>
            <translation>Nespuštěno: ventil nesleduje žádanou hodnotu: %1</translation>
        </message>
        <message>
            <source>At the present access level the result of this test cannot be accepted: %1

Switch to Expert first (View → Access level), or run the test now and switch before you accept: its result is kept. Start the test anyway?</source>
            <translation>Na současné úrovni oprávnění nelze výsledek této zkoušky převzít: %1

Nejprve přepněte na Expert (Náhled → Úroveň oprávnění), nebo zkoušku spusťte nyní a přepněte před převzetím: její výsledek zůstane zachován. Přesto zkoušku spustit?</translation>
        </message>
        <message>
            <source>The oscilloscope's setpoint generator is running: the test stops it (start it again afterwards).</source>
            <translation>Generátor žádané hodnoty osciloskopu běží: zkouška jej zastaví (poté jej spusťte znovu).</translation>
        </message>
        <message>
            <source>Stopping…</source>
            <translation>Přerušuje se…</translation>
        </message>
        <message>
            <source>Done.</source>
            <translation>Hotovo.</translation>
        </message>
        <message>
            <source>Stopped: %1</source>
            <translation>Přerušeno: %1</translation>
        </message>
        <message>
            <source>(View → Access level)</source>
            <translation>(Náhled → Úroveň oprávnění)</translation>
        </message>
        <message>
            <source>Not accepted: %1</source>
            <translation>Nepřevzato: %1</translation>
        </message>
        <message>
            <source>Accepted: %1</source>
            <translation>Převzato: %1</translation>
        </message>
        <message>
            <source>Tuning and characterization</source>
            <translation>Ladění a charakterizace</translation>
        </message>
        <message>
            <source>Position controller (spool)</source>
            <translation>Regulátor polohy (šoupátko)</translation>
        </message>
        <message>
            <source>Process controller (E04)</source>
            <translation>Regulátor procesní veličiny (E04)</translation>
        </message>
        <message>
            <source>Loop:</source>
            <translation>Regulační smyčka:</translation>
        </message>
        <message>
            <source>Stop</source>
            <translation>Stop</translation>
        </message>
        <message>
            <source>Offline: the tests run on the twin of serial {0} (fitted {1}, {2}) with the document's values.</source>
            <translation>Offline: zkoušky běží na dvojčeti výrobního čísla {0} (identifikováno {1}, {2}) s hodnotami dokumentu.</translation>
        </message>
        <message>
            <source>Offline: the tests run on an emulated valve with the document's values.</source>
            <translation>Offline: testy běží na emulovaném ventilu s hodnotami dokumentu.</translation>
        </message>
        <message>
            <source>The emulator's plant: this serial has no twin in the history.</source>
            <translation>Soustava emulátoru: toto výrobní číslo nemá v historii dvojče.</translation>
        </message>
        <message>
            <source>Online: the tests move the connected valve.</source>
            <translation>Online: testy pohybují připojeným ventilem.</translation>
        </message>
        <message>
            <source>Autotune</source>
            <translation>Autotune</translation>
        </message>
        <message>
            <source>Frequency response</source>
            <translation>Frekvenční charakteristika</translation>
        </message>
        <message>
            <source>Static characteristic</source>
            <translation>Statická charakteristika</translation>
        </message>
        <message>
            <source>Test report</source>
            <translation>Protokol o zkoušce</translation>
        </message>
        <message>
            <source>Ready.</source>
            <translation>Připraveno.</translation>
        </message>
        <message>
            <source>Birth certificate</source>
            <translation>Rodný list</translation>
        </message>
        <message>
            <source>Twin</source>
            <translation>Dvojče</translation>
        </message>
        <message>
            <source>Flow characteristic (E04)</source>
            <translation>Průtoková charakteristika (E04)</translation>
        </message>
    </context>
    <context>
        <name>TwinPage</name>
        <message>
            <source>Save the twin file</source>
            <translation>Uložit soubor dvojčete</translation>
        </message>
        <message>
            <source>Twin file (*.toml)</source>
            <translation>Soubor dvojčete (*.toml)</translation>
        </message>
        <message>
            <source>There is no folder %1 for the twin file.</source>
            <translation>Pro soubor dvojčete neexistuje složka %1.</translation>
        </message>
        <message>
            <source>A twin is fitted to a valve's own measurement: go online with the valve, or fit it from a characterization report (Fit from a report…).</source>
            <translation>Dvojče se identifikuje z měření samotného ventilu: přejděte s ventilem do režimu online, nebo je identifikujte ze zprávy charakterizace (Identifikovat ze zprávy…).</translation>
        </message>
        <message>
            <source>the end-of-line test (steps, a sine sweep and a triangle, about %1 s), then the twin fitted to it</source>
            <translation>výstupní zkoušku (skoky, sinusový rozmítaný signál a trojúhelník, asi %1 s), poté z ní identifikované dvojče</translation>
        </message>
        <message>
            <source>Characterization report</source>
            <translation>Zpráva charakterizace</translation>
        </message>
        <message>
            <source>JSON report (*.json)</source>
            <translation>Zpráva JSON (*.json)</translation>
        </message>
        <message>
            <source>Fitting the twin of %1…</source>
            <translation>Identifikuje se dvojče z %1…</translation>
        </message>
        <message>
            <source>Not fitted: %1</source>
            <translation>Neidentifikováno: %1</translation>
        </message>
        <message>
            <source>explained by the plant structure</source>
            <translation>vysvětleno strukturou soustavy</translation>
        </message>
        <message>
            <source>NOT explained by the plant structure: its constants are the best it allows</source>
            <translation>strukturou soustavy NEVYSVĚTLENO: její konstanty jsou to nejlepší, co dovoluje</translation>
        </message>
        <message>
            <source>Twin written to %1 and recorded in the history. Residual %2 % → %3 % rms (%4).</source>
            <translation>Dvojče zapsáno do %1 a zaznamenáno v historii. Reziduum %2 % → %3 % rms (%4).</translation>
        </message>
        <message>
            <source>Fitted: %1.</source>
            <translation>Identifikováno: %1.</translation>
        </message>
        <message>
            <source>The twin could not be characterized: %1</source>
            <translation>Dvojče nebylo možné charakterizovat: %1</translation>
        </message>
        <message>
            <source>The twin was characterized over: %1.</source>
            <translation>Dvojče bylo charakterizováno přes: %1.</translation>
        </message>
        <message>
            <source>determined</source>
            <translation>určeno</translation>
        </message>
        <message>
            <source>not determined, kept</source>
            <translation>neurčeno, ponecháno</translation>
        </message>
        <message>
            <source>(seen only with %1)</source>
            <translation>(viditelné jen společně s %1)</translation>
        </message>
        <message>
            <source>%1 pp (twin − valve)</source>
            <translation>%1 p. b. (dvojče − ventil)</translation>
        </message>
        <message>
            <source>×%1 (twin/valve)</source>
            <translation>×%1 (dvojče/ventil)</translation>
        </message>
        <message>
            <source>steps</source>
            <translation>skoky</translation>
        </message>
        <message>
            <source>sweep</source>
            <translation>rozmítání</translation>
        </message>
        <message>
            <source>static characteristic</source>
            <translation>statická charakteristika</translation>
        </message>
        <message>
            <source>A twin is the emulator's plant with the constants of this valve, fitted to its characterization (steps, sweep and static characteristic) and kept in a twin file with its serial and parameter set (docs/twin.md). Fit twin of the valve runs the end-of-line test of the profile chosen on the Test report page on the connected valve; Fit from a report… takes a characterization's JSON report (prm9tool --characterize --json) and its CSV files. Both record the twin in the history for the serial; offline tuning then runs on it.</source>
            <translation>Dvojče je soustava emulátoru s konstantami tohoto ventilu, identifikovanými z jeho charakterizace (skoky, rozmítání a statická charakteristika) a uloženými v souboru dvojčete s jeho výrobním číslem a sadou parametrů (docs/twin.md). „Identifikovat dvojče ventilu“ provede na připojeném ventilu výstupní zkoušku profilu zvoleného na stránce Protokol o zkoušce; „Identifikovat ze zprávy…“ vezme zprávu JSON charakterizace (prm9tool --characterize --json) s jejími soubory CSV. Obojí zaznamená dvojče v historii výrobního čísla; ladění offline pak běží na něm.</translation>
        </message>
        <message>
            <source>Twin file:</source>
            <translation>Soubor dvojčete:</translation>
        </message>
        <message>
            <source>Browse…</source>
            <translation>Procházet…</translation>
        </message>
        <message>
            <source>Fit twin of the valve</source>
            <translation>Identifikovat dvojče ventilu</translation>
        </message>
        <message>
            <source>Fit from a report…</source>
            <translation>Identifikovat ze zprávy…</translation>
        </message>
        <message>
            <source>Constant</source>
            <translation>Konstanta</translation>
        </message>
        <message>
            <source>Start</source>
            <translation>Počátek</translation>
        </message>
        <message>
            <source>Fitted</source>
            <translation>Identifikováno</translation>
        </message>
        <message>
            <source>Data</source>
            <translation>Data</translation>
        </message>
        <message>
            <source>Figure</source>
            <translation>Ukazatel</translation>
        </message>
        <message>
            <source>Valve</source>
            <translation>Ventil</translation>
        </message>
        <message>
            <source>Twin</source>
            <translation>Dvojče</translation>
        </message>
        <message>
            <source>Twin compared with valve</source>
            <translation>Dvojče ve srovnání s ventilem</translation>
        </message>
    </context>
    <context>
        <name>TypeKey</name>
        <message>
            <source>spool catalogue {0}: {1}</source>
            <translation>katalog šoupátek {0}: {1}</translation>
        </message>
        <message>
            <source>spool catalogue {0}: entry {1}: {2}</source>
            <translation>katalog šoupátek {0}: položka {1}: {2}</translation>
        </message>
        <message>
            <source>expected a list of spools</source>
            <translation>očekáván seznam šoupátek</translation>
        </message>
        <message>
            <source>expected an object with code, coils and description</source>
            <translation>očekáván objekt s code, coils a description</translation>
        </message>
        <message>
            <source>{0} is missing</source>
            <translation>{0} chybí</translation>
        </message>
        <message>
            <source>code {0} must be letters and digits only</source>
            <translation>code {0} smí obsahovat pouze písmena a číslice</translation>
        </message>
        <message>
            <source>spool {0} is named in the manual and cannot be redefined</source>
            <translation>šoupátko {0} je uvedeno v návodu a nelze ho předefinovat</translation>
        </message>
        <message>
            <source>coils {0} must be AB, A or B</source>
            <translation>coils {0} musí být AB, A nebo B</translation>
        </message>
        <message>
            <source>type key {0}: must start with 'PRM9-'</source>
            <translation>typový klíč {0}: musí začínat 'PRM9-'</translation>
        </message>
        <message>
            <source>type key {0}: nominal size {1} must be 06 or 10</source>
            <translation>typový klíč {0}: jmenovitá světlost {1} musí být 06 nebo 10</translation>
        </message>
        <message>
            <source>type key {0}: unknown spool {1} (known: {2})</source>
            <translation>typový klíč {0}: neznámé šoupátko {1} (známá: {2})</translation>
        </message>
        <message>
            <source>type key {0}: flow {1} l/min does not exist for Dn{2} (allowed: {3})</source>
            <translation>typový klíč {0}: jmenovitý průtok {1} l/min pro Dn{2} neexistuje (přípustné: {3})</translation>
        </message>
        <message>
            <source>type key {0}: supply voltage {1} must be 24</source>
            <translation>typový klíč {0}: napájecí napětí {1} musí být 24</translation>
        </message>
        <message>
            <source>type key {0}: configuration {1} must be E02 or E04</source>
            <translation>typový klíč {0}: konfigurace {1} musí být E02 nebo E04</translation>
        </message>
        <message>
            <source>type key {0}: suffix {1} must be empty or -CA</source>
            <translation>typový klíč {0}: přípona {1} musí být prázdná nebo -CA</translation>
        </message>
        <message>
            <source>type key {0}: expected '-' between the electronics series S02 and {1}</source>
            <translation>typový klíč {0}: mezi řadou elektroniky S02 a {1} chybí '-'</translation>
        </message>
        <message>
            <source>type key {0}: electronics series {1} must be S02</source>
            <translation>typový klíč {0}: řada elektroniky {1} musí být S02</translation>
        </message>
        <message>
            <source>type key {0}: expected '.' between the nominal size {1} and the spool, found {2}</source>
            <translation>typový klíč {0}: mezi jmenovitou světlostí {1} a šoupátkem se očekává '.', nalezeno: {2}</translation>
        </message>
        <message>
            <source>type key {0}: expected '/' between the spool {1} and the nominal flow, found {2}</source>
            <translation>typový klíč {0}: mezi šoupátkem {1} a jmenovitým průtokem se očekává '/', nalezeno: {2}</translation>
        </message>
        <message>
            <source>type key {0}: expected '-' between the nominal flow {1} and the supply voltage, found {2}</source>
            <translation>typový klíč {0}: mezi jmenovitým průtokem {1} a napájecím napětím se očekává '-', nalezeno: {2}</translation>
        </message>
        <message>
            <source>the end of the key</source>
            <translation>konec klíče</translation>
        </message>
        <message>
            <source>type key {0}: the {1} is missing</source>
            <translation>typový klíč {0}: chybí {1}</translation>
        </message>
        <message>
            <source>nominal size (06 or 10)</source>
            <translation>jmenovitá světlost (06 nebo 10)</translation>
        </message>
        <message>
            <source>spool</source>
            <translation>šoupátko</translation>
        </message>
        <message>
            <source>nominal flow</source>
            <translation>jmenovitý průtok</translation>
        </message>
        <message>
            <source>supply voltage (24)</source>
            <translation>napájecí napětí (24)</translation>
        </message>
        <message>
            <source>configuration (E02 or E04)</source>
            <translation>konfigurace (E02 nebo E04)</translation>
        </message>
        <message>
            <source>electronics series (S02)</source>
            <translation>řada elektroniky (S02)</translation>
        </message>
    </context>
    <context>
        <name>ValveConnection</name>
        <message>
            <source>The valve connection is busy; wait until it is done.</source>
            <translation>Spojení s ventilem je zaneprázdněno; počkejte na dokončení.</translation>
        </message>
        <message>
            <source>Already online; go offline first.</source>
            <translation>Již v režimu online; nejprve přejděte do režimu offline.</translation>
        </message>
        <message>
            <source>Not connected to a valve.</source>
            <translation>Není připojen žádný ventil.</translation>
        </message>
    </context>
    <context>
        <name>ValveControl</name>
        <message>
            <source>it is operational on CANopen but not enabled yet (device state {0}). Press Enable (control word 08h → 09h → 0Bh → 0Fh).</source>
            <translation>na sběrnici CANopen je ve stavu operational, ale ještě není uvolněn (stav zařízení {0}). Stiskněte „Uvolnit“ (řídicí slovo 08h → 09h → 0Bh → 0Fh).</translation>
        </message>
        <message>
            <source>no valve is connected.</source>
            <translation>není připojen žádný ventil.</translation>
        </message>
        <message>
            <source>the valve is starting up (about 2 s).</source>
            <translation>ventil se spouští (asi 2 s).</translation>
        </message>
        <message>
            <source>an error stops it (device state {0}); Valve → Valve status lists the error and resets it with Enable once the cause is gone.</source>
            <translation>zastavuje ho chyba (stav zařízení {0}); Ventil → Stav ventilu chybu uvádí a tlačítkem Uvolnit ji po odstranění příčiny resetuje.</translation>
        </message>
        <message>
            <source>it waits for a CANopen master (NMT {0}, device state {1}). Enable it under Valve → Valve status (control word 08h → 09h → 0Bh → 0Fh).</source>
            <translation>čeká na CANopen master (NMT {0}, stav zařízení {1}). Uvolněte ho v nabídce Ventil → Stav ventilu (řídicí slovo 08h → 09h → 0Bh → 0Fh).</translation>
        </message>
        <message>
            <source>its CANopen master stopped it (NMT stopped). Start it under Valve → Valve status.</source>
            <translation>jeho CANopen master ho zastavil (NMT zastaveno). Spusťte ho v nabídce Ventil → Stav ventilu.</translation>
        </message>
        <message>
            <source>it is not enabled (device state {0}). Enable it under Valve → Valve status.</source>
            <translation>není uvolněn (stav zařízení {0}). Uvolněte ho v nabídce Ventil → Stav ventilu.</translation>
        </message>
        <message>
            <source>it holds its position (device state HOLD). Enable it under Valve → Valve status.</source>
            <translation>drží svou polohu (stav zařízení HOLD). Uvolněte ho v nabídce Ventil → Stav ventilu.</translation>
        </message>
        <message>
            <source>an error stops it (device state {0}); the list of errors shows it. Press Enable once the cause is gone.</source>
            <translation>zastavila ho chyba (stav zařízení {0}); ukazuje ji seznam chyb. Po odstranění příčiny stiskněte „Uvolnit“.</translation>
        </message>
        <message>
            <source>it waits for a CANopen master (NMT {1}, device state {0}). Press NMT start, then Enable (control word 08h → 09h → 0Bh → 0Fh).</source>
            <translation>čeká na CANopen master (NMT {1}, stav zařízení {0}). Stiskněte „NMT start“ a pak „Uvolnit“ (řídicí slovo 08h → 09h → 0Bh → 0Fh).</translation>
        </message>
        <message>
            <source>its CANopen master stopped it (NMT stopped). Press NMT start.</source>
            <translation>jeho CANopen master ho zastavil (NMT zastaveno). Stiskněte „NMT start“.</translation>
        </message>
        <message>
            <source>it is not enabled (device state {0}). Press Enable.</source>
            <translation>není uvolněn (stav zařízení {0}). Stiskněte „Uvolnit“.</translation>
        </message>
        <message>
            <source>it holds its position (device state HOLD). Press Enable.</source>
            <translation>drží svou polohu (stav zařízení HOLD). Stiskněte „Uvolnit“.</translation>
        </message>
        <message>
            <source>offline</source>
            <translation>offline</translation>
        </message>
        <message>
            <source>starting up</source>
            <translation>spouští se</translation>
        </message>
        <message>
            <source>fault</source>
            <translation>chyba</translation>
        </message>
        <message>
            <source>waiting for a CANopen master</source>
            <translation>čeká na CANopen master</translation>
        </message>
        <message>
            <source>NMT stopped</source>
            <translation>NMT zastaveno</translation>
        </message>
        <message>
            <source>not enabled</source>
            <translation>neuvolněn</translation>
        </message>
        <message>
            <source>hold</source>
            <translation>držení</translation>
        </message>
    </context>
    <context>
        <name>ValveFinder</name>
        <message>
            <source>Listing the valves failed: {0}</source>
            <translation>Výpis ventilů selhal: {0}</translation>
        </message>
        <message>
            <source>Looking for valves…</source>
            <translation>Hledání ventilů…</translation>
        </message>
        <message>
            <source>Connecting to {0}…</source>
            <translation>Připojování k {0}…</translation>
        </message>
    </context>
    <context>
        <name>ValveRestarts</name>
        <message>
            <source>Restoring the factory values…</source>
            <translation>Obnovování továrního nastavení…</translation>
        </message>
        <message>
            <source>Restore factory values</source>
            <translation>Obnovit tovární nastavení</translation>
        </message>
        <message>
            <source>Set every parameter of the document to the factory default?</source>
            <translation>Nastavit všechny parametry dokumentu na tovární hodnoty?</translation>
        </message>
        <message>
            <source>Restarting the valve…</source>
            <translation>Restartování ventilu…</translation>
        </message>
        <message>
            <source>The valve restarted</source>
            <translation>Ventil byl restartován</translation>
        </message>
        <message>
            <source>{0} kbit/s</source>
            <translation>{0} kbit/s</translation>
        </message>
        <message>
            <source>The valve restarted at {0} {1}; prm9tool found it there</source>
            <translation>Ventil se restartoval jako {0} {1}; prm9tool ho tam našel</translation>
        </message>
        <message>
            <source>Factory values of the valve</source>
            <translation>Tovární nastavení ventilu</translation>
        </message>
        <message>
            <source>Factory values restored; the valve's previous parameters are in {0}</source>
            <translation>Tovární nastavení obnoveno; dosavadní parametry ventilu jsou v {0}</translation>
        </message>
        <message>
            <source>Factory values restored; the valve's backup from before is kept</source>
            <translation>Tovární nastavení obnoveno; dřívější záloha ventilu zůstává zachována</translation>
        </message>
    </context>
    <context>
        <name>ValveSelectionDialog</name>
        <message>
            <source>Valve selection</source>
            <translation>Výběr ventilu</translation>
        </message>
        <message>
            <source>Choose the valve by its type key. The new parameter set holds the factory defaults of that type; valve-specific calibration data is not included.</source>
            <translation>Zvolte ventil podle typového klíče. Nový záznam parametrů obsahuje tovární nastavení tohoto typu; kalibrační údaje konkrétního ventilu v něm nejsou obsaženy.</translation>
        </message>
        <message>
            <source>Nominal size:</source>
            <translation>Jmenovitá světlost:</translation>
        </message>
        <message>
            <source>Spool:</source>
            <translation>Šoupátko:</translation>
        </message>
        <message>
            <source>Nominal flow (Δp 10 bar):</source>
            <translation>Jmenovitý průtok (Δp 10 bar):</translation>
        </message>
        <message>
            <source>Supply voltage:</source>
            <translation>Napájecí napětí:</translation>
        </message>
        <message>
            <source>Configuration:</source>
            <translation>Konfigurace:</translation>
        </message>
        <message>
            <source>Interface:</source>
            <translation>Rozhraní:</translation>
        </message>
        <message>
            <source>Type key:</source>
            <translation>Typový klíč:</translation>
        </message>
        <message>
            <source>E02 – internal position feedback</source>
            <translation>E02 – interní polohová zpětná vazba</translation>
        </message>
        <message>
            <source>E04 – internal position and external feedback</source>
            <translation>E04 – interní polohová a externí zpětná vazba</translation>
        </message>
        <message>
            <source> (assumption)</source>
            <translation> (předpoklad)</translation>
        </message>
        <message>
            <source> (your spools.json)</source>
            <translation> (váš spools.json)</translation>
        </message>
        <message>
            <source>two solenoids A and B</source>
            <translation>dvě cívky A a B</translation>
        </message>
        <message>
            <source>one solenoid on side {0}</source>
            <translation>jedna cívka na straně {0}</translation>
        </message>
    </context>
    <context>
        <name>ValveStatusWindow</name>
        <message>
            <source>Valve status</source>
            <translation>Stav ventilu</translation>
        </message>
        <message>
            <source>Valve</source>
            <translation>Ventil</translation>
        </message>
        <message>
            <source>Active errors</source>
            <translation>Aktivní chyby</translation>
        </message>
        <message>
            <source>LEDs</source>
            <translation>LED</translation>
        </message>
        <message>
            <source>Mode:</source>
            <translation>Režim:</translation>
        </message>
        <message>
            <source>Firmware version:</source>
            <translation>Verze firmware:</translation>
        </message>
        <message>
            <source>Serial number:</source>
            <translation>Výrobní číslo:</translation>
        </message>
        <message>
            <source>Type key:</source>
            <translation>Typový klíč:</translation>
        </message>
        <message>
            <source>Device state:</source>
            <translation>Stav zařízení:</translation>
        </message>
        <message>
            <source>CANopen NMT state:</source>
            <translation>Stav NMT CANopen:</translation>
        </message>
        <message>
            <source>Temperature:</source>
            <translation>Teplota:</translation>
        </message>
        <message>
            <source>Supply voltage:</source>
            <translation>Napájecí napětí:</translation>
        </message>
        <message>
            <source>LED 1 power</source>
            <translation>LED 1 napájení</translation>
        </message>
        <message>
            <source>LED 2 error</source>
            <translation>LED 2 chyba</translation>
        </message>
        <message>
            <source>LED 3 CAN</source>
            <translation>LED 3 CAN</translation>
        </message>
        <message>
            <source>ONLINE</source>
            <translation>ONLINE</translation>
        </message>
        <message>
            <source>OFFLINE</source>
            <translation>OFFLINE</translation>
        </message>
        <message>
            <source>No status: the valve is offline.</source>
            <translation>Žádný stav: ventil je v režimu offline.</translation>
        </message>
        <message>
            <source>off (no CANopen)</source>
            <translation>vypnuto (bez CANopen)</translation>
        </message>
        <message>
            <source>initialising</source>
            <translation>inicializace</translation>
        </message>
        <message>
            <source>unknown</source>
            <translation>neznámý</translation>
        </message>
        <message>
            <source>white</source>
            <translation>bílá</translation>
        </message>
        <message>
            <source>green</source>
            <translation>zelená</translation>
        </message>
        <message>
            <source>orange</source>
            <translation>oranžová</translation>
        </message>
        <message>
            <source>red</source>
            <translation>červená</translation>
        </message>
        <message>
            <source>blue</source>
            <translation>modrá</translation>
        </message>
        <message>
            <source>magenta</source>
            <translation>purpurová</translation>
        </message>
        <message>
            <source>on</source>
            <translation>svítí</translation>
        </message>
        <message>
            <source>blinking 1 Hz</source>
            <translation>bliká 1 Hz</translation>
        </message>
        <message>
            <source>blinking 2 Hz</source>
            <translation>bliká 2 Hz</translation>
        </message>
        <message>
            <source>blinking 2.5 Hz</source>
            <translation>bliká 2,5 Hz</translation>
        </message>
        <message>
            <source>single flash</source>
            <translation>jednoduchý záblesk</translation>
        </message>
        <message>
            <source>double flash</source>
            <translation>dvojitý záblesk</translation>
        </message>
        <message>
            <source>triple flash</source>
            <translation>trojitý záblesk</translation>
        </message>
        <message>
            <source>quadruple flash</source>
            <translation>čtyřnásobný záblesk</translation>
        </message>
        <message>
            <source>power-up</source>
            <translation>zapínání</translation>
        </message>
        <message>
            <source>off</source>
            <translation>nesvítí</translation>
        </message>
        <message>
            <source>No error is present any more, but the valve still holds the fault (device state {0}): press Enable (control word 08h → 09h → 0Bh → 0Fh) to reset it.</source>
            <translation>Žádná chyba již netrvá, ventil však stále drží poruchu (stav zařízení {0}): stiskněte Uvolnit (řídicí slovo 08h → 09h → 0Bh → 0Fh) a resetujte ji.</translation>
        </message>
        <message>
            <source>No error.</source>
            <translation>Žádná chyba.</translation>
        </message>
    </context>
    <context>
        <name>ValveUpload</name>
        <message>
            <source>Nothing was sent to the valve</source>
            <translation>Do ventilu nebylo nic odesláno</translation>
        </message>
        <message>
            <source>Upload to valve</source>
            <translation>Načtení do ventilu</translation>
        </message>
        <message>
            <source>The document is for a {0} valve, the connected valve is a {1} valve. Choose the matching valve type or download the valve's parameters first.</source>
            <translation>Dokument je pro ventil {0}, připojený ventil je {1}. Zvolte odpovídající typ ventilu nebo nejprve stáhněte parametry z ventilu.</translation>
        </message>
        <message>
            <source>Uploading the parameters to the valve…</source>
            <translation>Načítání parametrů do ventilu…</translation>
        </message>
        <message>
            <source>Expert values at Basic level</source>
            <translation>Expertní hodnoty na základní úrovni</translation>
        </message>
        <message numerus="yes">
            <source>The document changes %n Expert-level value(s) of the valve ({0}), which the Basic access level cannot edit (controllers, linearizations, monitoring). Send them anyway?</source>
            <translation>
                <numerusform>Dokument mění %n hodnotu úrovně Expert ve ventilu ({0}), kterou základní úroveň oprávnění nemůže upravovat (regulátory, linearizace, monitorování). Přesto odeslat?</numerusform>
                <numerusform>Dokument mění %n hodnoty úrovně Expert ve ventilu ({0}), které základní úroveň oprávnění nemůže upravovat (regulátory, linearizace, monitorování). Přesto odeslat?</numerusform>
                <numerusform>Dokument mění %n hodnot úrovně Expert ve ventilu ({0}), které základní úroveň oprávnění nemůže upravovat (regulátory, linearizace, monitorování). Přesto odeslat?</numerusform>
            </translation>
        </message>
        <message>
            <source>Values written to the valve</source>
            <translation>Hodnoty zapsané do ventilu</translation>
        </message>
        <message numerus="yes">
            <source>%n parameter(s) written, verified and stored at {0}</source>
            <translation>
                <numerusform>%n parametr zapsán, ověřen a uložen v {0}</numerusform>
                <numerusform>%n parametry zapsány, ověřeny a uloženy v {0}</numerusform>
                <numerusform>%n parametrů zapsáno, ověřeno a uloženo v {0}</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n parameter(s) written, verified and stored again at {0}: the valve already held them</source>
            <translation>
                <numerusform>%n parametr znovu zapsán, ověřen a uložen v {0}: ventil jej již obsahoval</numerusform>
                <numerusform>%n parametry znovu zapsány, ověřeny a uloženy v {0}: ventil je již obsahoval</numerusform>
                <numerusform>%n parametrů znovu zapsáno, ověřeno a uloženo v {0}: ventil je již obsahoval</numerusform>
            </translation>
        </message>
        <message>
            <source>; Valve → Verify by restart… checks that it keeps them</source>
            <translation>; Ventil → Ověřit restartem… ověří, že si je ponechá</translation>
        </message>
        <message>
            <source>stored with 0x1010</source>
            <translation>uloženo pomocí 0x1010</translation>
        </message>
        <message>
            <source>kept by the valve as written (it has no store command)</source>
            <translation>ventil si hodnoty ponechal tak, jak byly zapsány (nemá příkaz k uložení)</translation>
        </message>
        <message>
            <source>verified after a restart</source>
            <translation>ověřeno po restartu</translation>
        </message>
        <message>
            <source>Upload failed</source>
            <translation>Načtení do ventilu selhalo</translation>
        </message>
        <message>
            <source>The upload failed at step “{0}”. Nothing was stored: after a restart the valve holds its previous parameters.</source>
            <translation>Načtení do ventilu selhalo v kroku „{0}“. Nic nebylo uloženo: po restartu má ventil své předchozí parametry.</translation>
        </message>
    </context>
    <context>
        <name>ValveWorkflow</name>
        <message>
            <source>Store changes in the valve</source>
            <translation>Uložit změny ve ventilu</translation>
        </message>
        <message>
            <source>Values changed online are active in the valve but not stored: a restart of the valve would undo them. Store them in the valve now?</source>
            <translation>Hodnoty změněné online jsou ve ventilu aktivní, ale neuložené: restart ventilu by je vrátil. Uložit je nyní do ventilu?</translation>
        </message>
        <message>
            <source>Offline</source>
            <translation>Offline</translation>
        </message>
        <message>
            <source>Reading the valve's parameters…</source>
            <translation>Čtení parametrů ventilu…</translation>
        </message>
        <message>
            <source>Back online: document and valve agree</source>
            <translation>Opět online: dokument a ventil se shodují</translation>
        </message>
        <message>
            <source>Online: document and valve agree</source>
            <translation>Online: dokument a ventil se shodují</translation>
        </message>
        <message>
            <source>Another valve</source>
            <translation>Jiný ventil</translation>
        </message>
        <message>
            <source>The document was read from valve {0}; you are online with valve {1} (serial numbers). Continue with this document on valve {1}?

Yes compares the two as usual (nothing is written unasked); No goes offline.</source>
            <translation>Dokument byl načten z ventilu {0}; v režimu online jste s ventilem {1} (výrobní čísla). Pokračovat s tímto dokumentem na ventilu {1}?

Ano je porovná jako obvykle (bez dotazu se nic nezapíše); Ne přejde do režimu offline.</translation>
        </message>
        <message>
            <source>Values read from the valve</source>
            <translation>Hodnoty načtené z ventilu</translation>
        </message>
        <message>
            <source>Online: parameters read from the valve</source>
            <translation>Online: parametry načteny z ventilu</translation>
        </message>
        <message>
            <source>{0}: the valve is a {1}, so the document is a new, unsaved one ({2} stays as it is)</source>
            <translation>{0}: ventil je {1}, proto je dokument nový, neuložený ({2} zůstává beze změny)</translation>
        </message>
        <message>
            <source>The valve reports an unknown type key: {0}</source>
            <translation>Ventil hlásí neznámý typový klíč: {0}</translation>
        </message>
        <message>
            <source>Nothing was sent to the valve</source>
            <translation>Do ventilu nebylo nic odesláno</translation>
        </message>
        <message>
            <source>Storing the parameters in the valve…</source>
            <translation>Ukládání parametrů do paměti ventilu…</translation>
        </message>
        <message>
            <source>Downloading the parameters from the valve…</source>
            <translation>Stahování parametrů z ventilu…</translation>
        </message>
        <message>
            <source>The valve's parameters are in the document; File → Save backup copy… keeps a copy of them</source>
            <translation>Parametry ventilu v dokumentu; zálohu uloží Soubor → Uložit záložní kopii…</translation>
        </message>
        <message>
            <source>The valve stored its parameters at {0}</source>
            <translation>Ventil uložil své parametry v {0}</translation>
        </message>
        <message>
            <source>Download from valve</source>
            <translation>Stažení z ventilu</translation>
        </message>
        <message>
            <source>Valve communication</source>
            <translation>Komunikace s ventilem</translation>
        </message>
        <message>
            <source>Connection to the valve lost; looking for it… ({0})</source>
            <translation>Spojení s ventilem ztraceno; hledá se… ({0})</translation>
        </message>
        <message>
            <source>The connection to the valve was lost; prm9tool is offline now and looks for the valve. When it is back, prm9tool compares it with the document and you decide what to do; nothing is sent again by itself.
Every value is kept in the document.</source>
            <translation>Spojení s ventilem bylo ztraceno; prm9tool je nyní offline a ventil hledá. Až bude ventil zpět, prm9tool jej porovná s dokumentem a o dalším postupu rozhodnete vy; nic se samo znovu neodešle.
Všechny hodnoty zůstávají v dokumentu.</translation>
        </message>
        <message>
            <source>Connection to the valve lost</source>
            <translation>Spojení s ventilem ztraceno</translation>
        </message>
        <message>
            <source>The connection to the valve was lost; prm9tool is offline now.
Every value is kept in the document: save it, or go online again and send it.</source>
            <translation>Spojení s ventilem bylo ztraceno; prm9tool je nyní v režimu offline.
Všechny hodnoty zůstávají v dokumentu: uložte jej, nebo přejděte znovu do režimu online a odešlete jej.</translation>
        </message>
        <message>
            <source>The valve {0} is back online; reading its parameters…</source>
            <translation>Ventil {0} je opět online; načítají se jeho parametry…</translation>
        </message>
        <message>
            <source>The valve is open again: what the setpoint generator cut off with the link had changed is as before ({0})</source>
            <translation>Ventil je opět připojen: co změnil generátor žádané hodnoty přerušený se spojením, je opět jako předtím ({0})</translation>
        </message>
        <message>
            <source>Another valve (serial number {0}) is where the lost valve {1} was ({2}). prm9tool does not connect to it by itself: it is a new valve. Go online to work with it.</source>
            <translation>Na místě ztraceného ventilu {1} ({2}) je jiný ventil (sériové číslo {0}). prm9tool se k němu sám nepřipojí: je to nový ventil. Chcete-li s ním pracovat, přejděte do režimu online.</translation>
        </message>
        <message>
            <source>Backup of the valve's parameters saved: {0}</source>
            <translation>Záloha parametrů ventilu uložena: {0}</translation>
        </message>
    </context>
</TS>
