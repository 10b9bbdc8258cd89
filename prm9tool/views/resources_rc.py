# Resource object code (Python 3)
# Created by: object code
# Created by: The Resource Compiler for Qt version 6.11.3
# WARNING! All changes made in this file will be lost!

from PySide6 import QtCore

qt_resource_data = b"\
\x00\x00\x12\x1a\
<\
!DOCTYPE html>\x0a<\
html lang=\x22cs\x22>\x0a\
<head><meta char\
set=\x22utf-8\x22><tit\
le>prm9tool \xe2\x80\x93 \
n\xc3\xa1pov\xc4\x9bda</titl\
e></head>\x0a<body>\
\x0a<h1>prm9tool</h\
1>\x0a<p>prm9tool n\
astavuje paramet\
ry proporcion\xc3\xa1l\
n\xc3\xadch rozv\xc3\xa1d\xc4\x9b\xc4\
\x8d\xc5\xaf PRM9 s integ\
rovanou digit\xc3\xa1l\
n\xc3\xad\x0aelektronikou\
 \xe2\x80\x93 p\xc5\x99es USB n\
ebo na vestav\xc4\x9bn\
\xc3\xa9m emulovan\xc3\xa9m \
ventilu. Paramet\
ry popisuje p\xc5\x99\xc3\
\xadru\xc4\x8dka\x0aventilu \
(kapitola 8); ta\
to str\xc3\xa1nka popi\
suje program.</p\
>\x0a\x0a<h2>Spu\xc5\xa1t\xc4\x9bn\
\xc3\xad</h2>\x0a<ul>\x0a<li\
><code>prm9tool<\
/code> otev\xc5\x99e o\
kno s nov\xc3\xbdm z\xc3\xa1\
znamem parametr\xc5\
\xaf.</li>\x0a<li><cod\
e>prm9tool SOUBO\
R.prm</code> ote\
v\xc5\x99e z\xc3\xa1znam par\
ametr\xc5\xaf.</li>\x0a<l\
i><code>prm9tool\
 --emulator [TYP\
OV\xc3\x9d_KL\xc3\x8d\xc4\x8c[:V\xc3\x9d\
ROBN\xc3\x8d_\xc4\x8c\xc3\x8dSLO]]\
</code> spust\xc3\xad \
program v re\xc5\xbeim\
u\x0aonline s emulo\
van\xc3\xbdm ventilem \
(v\xc3\xbdchoz\xc3\xad typov\
\xc3\xbd kl\xc3\xad\xc4\x8d <code>\
PRM9-06.3Z11/30-\
24E02S02-CA</cod\
e>).</li>\x0a</ul>\x0a\
\x0a<h2>Okno</h2>\x0a<\
p>Hlavn\xc3\xad menu, \
panel n\xc3\xa1stroj\xc5\xaf\
, hlavn\xc3\xad plocha\
 a stavov\xc3\xbd \xc5\x99\xc3\xa1\
dek. Stavov\xc3\xbd \xc5\x99\
\xc3\xa1dek zobrazuje \
re\xc5\xbeim\x0akomunikac\
e, stav elektron\
iky ventilu (<i>\
ok</i> nebo akti\
vn\xc3\xad chybu), ver\
zi firmware, typ\
ov\xc3\xbd\x0akl\xc3\xad\xc4\x8d a n\xc3\
\xa1zev souboru; <b\
>*</b> ozna\xc4\x8duje\
 neulo\xc5\xbeen\xc3\xa9 zm\xc4\
\x9bny; nakonec \xc3\xbar\
ove\xc5\x88 opr\xc3\xa1vn\xc4\x9bn\
\xc3\xad. Re\xc5\xbeim\x0aukazu\
je P\xc5\x98IPOJOV\xc3\x81N\xc3\
\x8d, dokud se pr\xc3\xa1\
v\xc4\x9b p\xc5\x99ipojen\xc3\xbd \
ventil porovn\xc3\xa1v\
\xc3\xa1 se sadou para\
metr\xc5\xaf, a ONLINE\
,\x0ajakmile se sho\
duj\xc3\xad.</p>\x0a<p>Hl\
avn\xc3\xad plocha zob\
razuje jeden ze \
t\xc5\x99\xc3\xad n\xc3\xa1hled\xc5\xaf:\
 <b>postupov\xc3\xbd d\
iagram</b> (klik\
nut\xc3\xadm na blok\x0an\
astav\xc3\xadte jeho p\
arametry, kliknu\
t\xc3\xadm na \xc4\x8derven\xc3\
\xbd m\xc4\x9b\xc5\x99ic\xc3\xad bod \
jej zobraz\xc3\xadte v\
 osciloskopu),\x0a<\
b>seznam paramet\
r\xc5\xaf</b> (dvojkli\
kem na \xc5\x99\xc3\xa1dek z\
m\xc4\x9bn\xc3\xadte hodnotu\
; hodnoty odli\xc5\xa1\
n\xc3\xa9 od tov\xc3\xa1rn\xc3\xad\
ho\x0anastaven\xc3\xad js\
ou zv\xc3\xbdrazn\xc4\x9bny;\
 hled\xc3\xa1n\xc3\xad a \xe2\x80\x9e\
Jen zm\xc4\x9bn\xc4\x9bn\xc3\xa9\xe2\x80\
\x9c seznam filtruj\
\xc3\xad) a <b>oscilos\
kop</b>\x0a(pouze v\
 re\xc5\xbeimu online,\
 nejv\xc3\xbd\xc5\xa1e t\xc5\x99i \
m\xc4\x9b\xc5\x99ic\xc3\xad body).\
</p>\x0a\x0a<h2>\xc3\x9arovn\
\xc4\x9b opr\xc3\xa1vn\xc4\x9bn\xc3\xad<\
/h2>\x0a<p><b>Z\xc3\xa1kl\
adn\xc3\xad</b> \xc3\xbarove\
\xc5\x88 zobrazuje z\xc3\xa1\
kladn\xc3\xad nastaven\
\xc3\xad; na z\xc3\xa1kladn\xc3\
\xad \xc3\xbarovni se \xc4\x8dt\
y\xc5\x99i rampy\x0anasta\
vuj\xc3\xad spole\xc4\x8dn\xc4\x9b\
. <b>Expertn\xc3\xad</\
b> \xc3\xbarove\xc5\x88 p\xc5\x99i\
d\xc3\xa1v\xc3\xa1 regul\xc3\xa1to\
ry, linearizace \
a nastaven\xc3\xad\x0aext\
ern\xc3\xadho sn\xc3\xadma\xc4\x8d\
e a je chr\xc3\xa1n\xc4\x9bn\
a heslem. Heslo \
p\xc5\x99i dod\xc3\xa1n\xc3\xad je\
 <code>expert</c\
ode>; na expertn\
\xc3\xad\x0a\xc3\xbarovni jej z\
m\xc4\x9bn\xc3\xadte v menu \
N\xc3\xa1hled \xe2\x86\x92 \xc3\x9aro\
ve\xc5\x88 opr\xc3\xa1vn\xc4\x9bn\xc3\
\xad \xe2\x86\x92 Zm\xc4\x9bnit he\
slo pro expertn\xc3\
\xad \xc3\xbarove\xc5\x88.\x0aProg\
ram ukl\xc3\xa1d\xc3\xa1 pou\
ze jeho osolen\xc3\xbd\
 hash.</p>\x0a\x0a<h2>\
Online a offline\
</h2>\x0a<p>Komunik\
ace \xe2\x86\x92 HID konf\
igurace zobraz\xc3\xad\
 ventily p\xc5\x99ipoj\
en\xc3\xa9 p\xc5\x99es USB a\
 emulovan\xc3\xa9 vent\
ily;\x0aemulovan\xc3\xbd \
ventil p\xc5\x99id\xc3\xa1te\
 zad\xc3\xa1n\xc3\xadm typov\
\xc3\xa9ho kl\xc3\xad\xc4\x8de a v\
\xc3\xbdrobn\xc3\xadho \xc4\x8d\xc3\xads\
la. Komunikace \xe2\
\x86\x92 Re\xc5\xbeim online\
\x0anav\xc3\xa1\xc5\xbee spojen\
\xc3\xad. Li\xc5\xa1\xc3\xad-li se\
 otev\xc5\x99en\xc3\xbd z\xc3\xa1z\
nam parametr\xc5\xaf o\
d ventilu, progr\
am zobraz\xc3\xad rozd\
\xc3\xadly a\x0azept\xc3\xa1 se\
, zda p\xc5\x99evz\xc3\xadt \
hodnoty ventilu,\
 odeslat hodnoty\
 dokumentu (na\xc4\x8d\
ten\xc3\xad do ventilu\
) nebo\x0azru\xc5\xa1it. \
V re\xc5\xbeimu online\
 jde ka\xc5\xbed\xc3\xa1 zm\xc4\
\x9bna ihned do ven\
tilu i do dokume\
ntu, v re\xc5\xbeimu o\
ffline\x0apouze do \
dokumentu. Ztrat\
\xc3\xad-li se spojen\xc3\
\xad s ventilem, pr\
ogram p\xc5\x99ejde do\
 re\xc5\xbeimu offline\
 a\x0av\xc5\xa1echny hodn\
oty zachov\xc3\xa1.</p\
>\x0a<p>Hodnoty zm\xc4\
\x9bn\xc4\x9bn\xc3\xa9 online j\
sou ve ventilu a\
ktivn\xc3\xad, ale je\xc5\
\xa1t\xc4\x9b neulo\xc5\xbeen\xc3\xa9\
: p\xc5\x99i p\xc5\x99echodu\
 do\x0are\xc5\xbeimu offl\
ine program nab\xc3\
\xaddne jejich ulo\xc5\
\xbeen\xc3\xad. <b>Na\xc4\x8dte\
n\xc3\xad do ventilu</\
b> zap\xc3\xad\xc5\xa1e v\xc5\xa1e\
chny\x0ahodnoty, p\xc5\
\x99e\xc4\x8dte je zp\xc4\x9bt,\
 porovn\xc3\xa1 a ulo\xc5\
\xbe\xc3\xad; ulo\xc5\xbe\xc3\xad se \
jen tehdy, je-li\
 ka\xc5\xbed\xc3\xa1 hodnota\
 ov\xc4\x9b\xc5\x99ena.\x0aP\xc5\x99e\
d prvn\xc3\xadm na\xc4\x8dte\
n\xc3\xadm do ventilu \
program ulo\xc5\xbe\xc3\xad \
z\xc3\xa1lohu vlastn\xc3\xad\
ch parametr\xc5\xaf ve\
ntilu do slo\xc5\xbeky\
\x0au\xc5\xbeivatelsk\xc3\xbdch\
 dat (<code>back\
ups/&lt;v\xc3\xbdrobn\xc3\
\xad \xc4\x8d\xc3\xadslo&gt;/</\
code>).</p>\x0a<p><\
b>Restart ventil\
u</b> a <b>Obnov\
en\xc3\xad tov\xc3\xa1rn\xc3\xadho\
 nastaven\xc3\xad</b> \
jsou dovoleny po\
uze p\xc5\x99i\x0aodpojen\
\xc3\xa9m hydraulick\xc3\xa9\
m obvodu; progra\
m v\xc3\xa1s po\xc5\xbe\xc3\xa1d\xc3\xa1\
 o potvrzen\xc3\xad.</\
p>\x0a\x0a<h2>Soubory<\
/h2>\x0a<p>Z\xc3\xa1znamy\
 parametr\xc5\xaf (<co\
de>*.prm</code>)\
 jsou textov\xc3\xa9 s\
oubory. Otev\xc5\x99\xc3\xad\
t, Ulo\xc5\xbeit, Ulo\xc5\
\xbeit jako,\x0anaposl\
edy otev\xc5\x99en\xc3\xa9 s\
oubory a p\xc5\x99eta\xc5\
\xbeen\xc3\xad my\xc5\xa1\xc3\xad fun\
guj\xc3\xad obvykl\xc3\xbdm \
zp\xc5\xafsobem; p\xc5\x99ed\
 ztr\xc3\xa1tou\x0aneulo\xc5\
\xbeen\xc3\xbdch zm\xc4\x9bn se\
 program zept\xc3\xa1.\
 Ka\xc5\xbedou zm\xc4\x9bnu \
lze vr\xc3\xa1tit (Ctr\
l+Z) a znovu pro\
v\xc3\xa9st\x0a(Ctrl+Y). \
Soubor \xe2\x86\x92 Tisk \
a Soubor \xe2\x86\x92 Exp\
ort do PDF vytvo\
\xc5\x99\xc3\xad protokol pa\
rametr\xc5\xaf s typov\
\xc3\xbdm kl\xc3\xad\xc4\x8dem,\x0av\xc3\
\xbdrobn\xc3\xadm \xc4\x8d\xc3\xadsle\
m, firmware, sou\
borem, datem, \xc3\xba\
rovn\xc3\xad opr\xc3\xa1vn\xc4\x9b\
n\xc3\xad, postupov\xc3\xbdm\
 diagramem a v\xc5\xa1\
emi\x0aparametry s \
jednotkami.</p>\x0a\
\x0a<h2>Kl\xc3\xa1vesnice\
</h2>\x0a<table>\x0a<t\
r><td>Ctrl+O / C\
trl+S / Ctrl+Shi\
ft+S</td><td>Ote\
v\xc5\x99\xc3\xadt / Ulo\xc5\xbeit\
 / Ulo\xc5\xbeit jako<\
/td></tr>\x0a<tr><t\
d>Ctrl+Z / Ctrl+\
Y</td><td>Zp\xc4\x9bt \
/ Znovu</td></tr\
>\x0a<tr><td>Ctrl+P\
 / Ctrl+E</td><t\
d>Tisk / Export \
do PDF</td></tr>\
\x0a<tr><td>Ctrl+1 \
/ Ctrl+2 / Ctrl+\
3 / Ctrl+4</td><\
td>Postupov\xc3\xbd di\
agram / Seznam p\
arametr\xc5\xaf / Osci\
loskop / Okno CA\
Nopen</td></tr>\x0a\
<tr><td>F5 / Shi\
ft+F5</td><td>Re\
\xc5\xbeim online / Re\
\xc5\xbeim offline</td\
></tr>\x0a<tr><td>C\
trl+U / Ctrl+D</\
td><td>Na\xc4\x8dten\xc3\xad\
 do ventilu / St\
a\xc5\xbeen\xc3\xad z ventil\
u</td></tr>\x0a<tr>\
<td>Ctrl+T / Ctr\
l+I / Ctrl+H</td\
><td>V\xc3\xbdb\xc4\x9br ven\
tilu / Stav vent\
ilu / HID konfig\
urace</td></tr>\x0a\
</table>\x0a</body>\
\x0a</html>\x0a\
\x00\x00\x12r\
<\
!DOCTYPE html>\x0a<\
html lang=\x22de\x22>\x0a\
<head><meta char\
set=\x22utf-8\x22><tit\
le>prm9tool \xe2\x80\x93 \
Hilfe</title></h\
ead>\x0a<body>\x0a<h1>\
prm9tool</h1>\x0a<p\
>prm9tool stellt\
 die Parameter v\
on PRM9-Proporti\
onal-Wegeventile\
n mit integriert\
er\x0adigitaler Ele\
ktronik ein \xe2\x80\x93 \
\xc3\xbcber USB oder a\
m eingebauten em\
ulierten Ventil.\
 Die Parameter\x0ab\
eschreibt die Be\
triebsanleitung \
des Ventils (Kap\
itel 8); diese S\
eite beschreibt \
das\x0aProgramm.</p\
>\x0a\x0a<h2>Start</h2\
>\x0a<ul>\x0a<li><code\
>prm9tool</code>\
 \xc3\xb6ffnet das Fen\
ster mit einem n\
euen Parametersa\
tz.</li>\x0a<li><co\
de>prm9tool DATE\
I.prm</code> \xc3\xb6f\
fnet eine Parame\
terdatei.</li>\x0a<\
li><code>prm9too\
l --emulator [TY\
PSCHL\xc3\x9cSSEL[:SER\
IENNUMMER]]</cod\
e> startet onlin\
e mit einem\x0aemul\
ierten Ventil (S\
tandard-Typschl\xc3\
\xbcssel <code>PRM9\
-06.3Z11/30-24E0\
2S02-CA</code>).\
</li>\x0a</ul>\x0a\x0a<h2\
>Das Fenster</h2\
>\x0a<p>Hauptmen\xc3\xbc,\
 Werkzeugleiste,\
 Hauptfl\xc3\xa4che un\
d Statuszeile. D\
ie Statuszeile z\
eigt den\x0aKommuni\
kationsmodus, de\
n Zustand des Ve\
ntils (<i>ok</i>\
 oder den aktive\
n Fehler), die\x0aF\
irmware-Version,\
 den Typschl\xc3\xbcss\
el und den Datei\
namen (<b>*</b>:\
 ungespeicherte \
\xc3\x84nderungen)\x0aund\
 zuletzt die Ber\
echtigungsstufe.\
 Der Modus laute\
t VERBINDEN, sol\
ange ein eben ve\
rbundenes\x0aVentil\
 mit dem Paramet\
ersatz vergliche\
n wird, und ONLI\
NE, sobald beide\
 \xc3\xbcbereinstimmen\
.</p>\x0a<p>Die Hau\
ptfl\xc3\xa4che zeigt \
eine von drei An\
sichten: das <b>\
Ablaufdiagramm</\
b> (ein Klick au\
f\x0aeinen Block st\
ellt seine Param\
eter ein, ein Kl\
ick auf einen ro\
ten Messpunkt ze\
igt ihn im\x0aOszil\
loskop), die <b>\
Parameterliste</\
b> (Doppelklick \
auf eine Zeile \xc3\
\xa4ndert den Wert;\
 Werte,\x0adie von \
der Werkseinstel\
lung abweichen, \
sind hervorgehob\
en; Suche und \xe2\x80\
\x9eNur ge\xc3\xa4nderte\xe2\
\x80\x9c\x0afiltern die L\
iste) und das <b\
>Oszilloskop</b>\
 (nur online, h\xc3\
\xb6chstens drei Me\
sspunkte).</p>\x0a\x0a\
<h2>Berechtigung\
sstufen</h2>\x0a<p>\
<b>Basis</b> zei\
gt die grundlege\
nden Einstellung\
en; in der Basis\
stufe werden die\
 vier\x0aRampen gem\
einsam eingestel\
lt. <b>Experte</\
b> erg\xc3\xa4nzt die \
Regler, die Line\
arisierungen und\
\x0adie Einstellung\
en des externen \
Sensors und ist \
durch ein Passwo\
rt gesch\xc3\xbctzt. D\
as Passwort\x0aim A\
uslieferungszust\
and lautet <code\
>expert</code>; \
in der Expertens\
tufe \xc3\xa4ndern Sie\
 es unter\x0aAnsich\
t \xe2\x86\x92 Berechtigu\
ngsstufe \xe2\x86\x92 Exp\
ertenpasswort \xc3\xa4\
ndern. Das Progr\
amm speichert nu\
r einen\x0agesalzen\
en Hash davon.</\
p>\x0a\x0a<h2>Online u\
nd offline</h2>\x0a\
<p>Kommunikation\
 \xe2\x86\x92 HID-Konfigu\
ration listet di\
e \xc3\xbcber USB ange\
schlossenen und \
die emulierten\x0aV\
entile; ein emul\
iertes Ventil f\xc3\
\xbcgen Sie mit Typ\
schl\xc3\xbcssel und S\
eriennummer hinz\
u.\x0aKommunikation\
 \xe2\x86\x92 Online-Modu\
s verbindet. Wei\
cht der ge\xc3\xb6ffne\
te Parametersatz\
 vom Ventil ab,\x0a\
zeigt das Progra\
mm die Unterschi\
ede und fragt, o\
b die Werte des \
Ventils \xc3\xbcbernom\
men, die\x0aWerte d\
es Dokuments ges\
endet (Hochladen\
) oder abgebroch\
en werden soll. \
Online geht jede\
\x0a\xc3\x84nderung sofor\
t an das Ventil \
und in das Dokum\
ent, offline nur\
 in das Dokument\
. Geht die\x0aVerbi\
ndung verloren, \
schaltet das Pro\
gramm auf offlin\
e und beh\xc3\xa4lt al\
le Werte.</p>\x0a<p\
>Online ge\xc3\xa4nder\
te Werte sind im\
 Ventil aktiv, a\
ber noch nicht g\
espeichert: beim\
 Wechsel\x0aauf off\
line bietet das \
Programm an, sie\
 zu speichern. <\
b>In das Ventil \
hochladen</b>\x0asc\
hreibt alle Wert\
e, liest sie zur\
\xc3\xbcck, vergleicht\
 und speichert s\
ie; gespeichert \
wird nur,\x0awenn j\
eder Wert best\xc3\xa4\
tigt wurde. Vor \
dem ersten Hochl\
aden in ein Vent\
il sichert das\x0aP\
rogramm dessen e\
igene Parameter \
im Benutzerdaten\
ordner (<code>ba\
ckups/&lt;Serien\
nummer&gt;/</cod\
e>).</p>\x0a<p><b>V\
entil neu starte\
n</b> und <b>Wer\
kseinstellungen \
wiederherstellen\
</b> sind nur be\
i\x0agetrennter Hyd\
raulik erlaubt; \
das Programm l\xc3\xa4\
sst Sie das best\
\xc3\xa4tigen.</p>\x0a\x0a<h\
2>Dateien</h2>\x0a<\
p>Parameterdatei\
en (<code>*.prm<\
/code>) sind Tex\
tdateien. \xc3\x96ffne\
n, Speichern, Sp\
eichern\x0aunter, d\
ie zuletzt ge\xc3\xb6f\
fneten Dateien u\
nd Drag &amp; Dr\
op funktionieren\
 wie gewohnt; vo\
r dem\x0aVerlust un\
gespeicherter \xc3\x84\
nderungen fragt \
das Programm nac\
h. Jede \xc3\x84nderun\
g l\xc3\xa4sst sich\x0ar\xc3\
\xbcckg\xc3\xa4ngig mache\
n (Strg+Z) und w\
iederherstellen \
(Strg+Y). Datei \
\xe2\x86\x92 Drucken und \
Datei \xe2\x86\x92 PDF\x0aex\
portieren erzeug\
en ein Parameter\
protokoll mit Ty\
pschl\xc3\xbcssel, Ser\
iennummer, Firmw\
are, Datei,\x0aDatu\
m, Berechtigungs\
stufe, dem Ablau\
fdiagramm und al\
len Parametern m\
it Einheit.</p>\x0a\
\x0a<h2>Tastatur</h\
2>\x0a<table>\x0a<tr><\
td>Strg+O / Strg\
+S / Strg+Umscha\
lt+S</td><td>\xc3\x96f\
fnen / Speichern\
 / Speichern unt\
er</td></tr>\x0a<tr\
><td>Strg+Z / St\
rg+Y</td><td>R\xc3\xbc\
ckg\xc3\xa4ngig / Wied\
erherstellen</td\
></tr>\x0a<tr><td>S\
trg+P / Strg+E</\
td><td>Drucken /\
 PDF exportieren\
</td></tr>\x0a<tr><\
td>Strg+1 / Strg\
+2 / Strg+3 / St\
rg+4</td><td>Abl\
aufdiagramm / Pa\
rameterliste / O\
szilloskop / CAN\
open-Fenster</td\
></tr>\x0a<tr><td>F\
5 / Umschalt+F5<\
/td><td>Online /\
 Offline</td></t\
r>\x0a<tr><td>Strg+\
U / Strg+D</td><\
td>In das Ventil\
 hochladen / Aus\
 dem Ventil heru\
nterladen</td></\
tr>\x0a<tr><td>Strg\
+T / Strg+I / St\
rg+H</td><td>Ven\
tilauswahl / Ven\
tilstatus / HID-\
Konfiguration</t\
d></tr>\x0a</table>\
\x0a</body>\x0a</html>\
\x0a\
\x00\x00\x10\x10\
<\
!DOCTYPE html>\x0a<\
html lang=\x22en\x22>\x0a\
<head><meta char\
set=\x22utf-8\x22><tit\
le>prm9tool help\
</title></head>\x0a\
<body>\x0a<h1>prm9t\
ool</h1>\x0a<p>prm9\
tool sets the pa\
rameters of PRM9\
 proportional di\
rectional valves\
 with integrated\
\x0adigital electro\
nics, over USB o\
r on the built-i\
n emulated valve\
. The valve's ow\
n manual\x0a(chapte\
r 8) describes t\
he parameters; t\
his page describ\
es the program.<\
/p>\x0a\x0a<h2>Startin\
g</h2>\x0a<ul>\x0a<li>\
<code>prm9tool</\
code> opens the \
window with a ne\
w parameter set.\
</li>\x0a<li><code>\
prm9tool FILE.pr\
m</code> opens a\
 parameter file.\
</li>\x0a<li><code>\
prm9tool --emula\
tor [TYPEKEY[:SE\
RIAL]]</code> st\
arts online with\
 an emulated val\
ve\x0a(default type\
 key <code>PRM9-\
06.3Z11/30-24E02\
S02-CA</code>).<\
/li>\x0a</ul>\x0a\x0a<h2>\
The window</h2>\x0a\
<p>Main menu, to\
olbar, main area\
 and status bar.\
 The status bar \
shows the commun\
ication mode,\x0ath\
e valve state (<\
i>ok</i> or the \
active error), t\
he firmware vers\
ion, the type ke\
y and the\x0afile n\
ame; <b>*</b> ma\
rks unsaved chan\
ges; last the ac\
cess level. The \
mode reads CONNE\
CTING\x0awhile a va\
lve just connect\
ed is compared w\
ith the paramete\
r set, and ONLIN\
E once they agre\
e.</p>\x0a<p>The ma\
in area shows on\
e of three views\
: the <b>flow di\
agram</b> (click\
 a block to set \
its\x0aparameters, \
click a red meas\
uring point to w\
atch it in the o\
scilloscope), th\
e\x0a<b>parameter l\
ist</b> (double-\
click a row to c\
hange the value;\
 values that dif\
fer from the\x0afac\
tory defaults ar\
e highlighted; s\
earch and \xe2\x80\x9cMod\
ified only\xe2\x80\x9d fi\
lter the list) a\
nd the\x0a<b>oscill\
oscope</b> (onli\
ne only, at most\
 three measuring\
 points).</p>\x0a\x0a<\
h2>Access levels\
</h2>\x0a<p><b>Basi\
c</b> shows the \
basic settings; \
at Basic level t\
he four ramps ar\
e set together.\x0a\
<b>Expert</b> ad\
ds the controlle\
rs, the lineariz\
ations and the e\
xternal-sensor s\
ettings and\x0ais p\
rotected by a pa\
ssword. The pass\
word as delivere\
d is <code>exper\
t</code>; change\
 it at\x0aExpert le\
vel with View \xe2\x86\
\x92 Access level \xe2\
\x86\x92 Change Expert\
 password. The p\
rogram keeps onl\
y a\x0asalted hash \
of it.</p>\x0a\x0a<h2>\
Online and offli\
ne</h2>\x0a<p>Commu\
nication \xe2\x86\x92 HID\
 configuration l\
ists the valves \
connected over U\
SB and the emula\
ted\x0avalves; add \
an emulated valv\
e with its type \
key and serial n\
umber. Communica\
tion \xe2\x86\x92 Online\x0a\
mode connects. I\
f the open param\
eter set differs\
 from the valve'\
s, the program l\
ists the\x0adiffere\
nces and asks wh\
ether to take th\
e valve's values\
, send the docum\
ent's values\x0a(up\
load) or cancel.\
 Online, every c\
hange goes to th\
e valve at once \
and into the doc\
ument;\x0aoffline, \
into the documen\
t only. If the v\
alve is lost, th\
e program goes o\
ffline and keeps\
\x0aevery value.</p\
>\x0a<p>Values chan\
ged online are a\
ctive in the val\
ve but not yet s\
tored: going off\
line offers to\x0as\
tore them. <b>Up\
load to valve</b\
> writes all val\
ues, reads them \
back, compares a\
nd stores\x0athem; \
nothing is store\
d unless every v\
alue was verifie\
d. Before the fi\
rst upload to a \
valve\x0athe progra\
m saves a backup\
 of the valve's \
own parameters i\
n the user data \
folder\x0a(<code>ba\
ckups/&lt;serial\
&gt;/</code>).</\
p>\x0a<p><b>Restart\
 valve</b> and <\
b>Restore factor\
y values</b> are\
 allowed only wi\
th the\x0ahydraulic\
s disconnected; \
the program asks\
 you to confirm \
this.</p>\x0a\x0a<h2>F\
iles</h2>\x0a<p>Par\
ameter files (<c\
ode>*.prm</code>\
) are text files\
. Open, Save, Sa\
ve As, the recen\
t\x0afiles and drag\
 and drop work a\
s usual; the pro\
gram asks before\
 unsaved changes\
 are lost.\x0aEvery\
 change can be u\
ndone (Ctrl+Z) a\
nd redone (Ctrl+\
Y). File \xe2\x86\x92 Pri\
nt and File \xe2\x86\x92 \
Export PDF\x0aprodu\
ce a parameter r\
ecord with type \
key, serial numb\
er, firmware, fi\
le, date, access\
 level,\x0athe flow\
 diagram and eve\
ry parameter wit\
h its unit.</p>\x0a\
\x0a<h2>Keyboard</h\
2>\x0a<table>\x0a<tr><\
td>Ctrl+O / Ctrl\
+S / Ctrl+Shift+\
S</td><td>Open /\
 Save / Save As<\
/td></tr>\x0a<tr><t\
d>Ctrl+Z / Ctrl+\
Y</td><td>Undo /\
 Redo</td></tr>\x0a\
<tr><td>Ctrl+P /\
 Ctrl+E</td><td>\
Print / Export P\
DF</td></tr>\x0a<tr\
><td>Ctrl+1 / Ct\
rl+2 / Ctrl+3 / \
Ctrl+4</td><td>F\
low diagram / Pa\
rameter list / O\
scilloscope / CA\
Nopen window</td\
></tr>\x0a<tr><td>F\
5 / Shift+F5</td\
><td>Online / Of\
fline</td></tr>\x0a\
<tr><td>Ctrl+U /\
 Ctrl+D</td><td>\
Upload to valve \
/ Download from \
valve</td></tr>\x0a\
<tr><td>Ctrl+T /\
 Ctrl+I / Ctrl+H\
</td><td>Valve s\
election / Valve\
 status / HID co\
nfiguration</td>\
</tr>\x0a</table>\x0a<\
/body>\x0a</html>\x0a\
\x00\x00\x01\xc2\
<\
svg xmlns=\x22http:\
//www.w3.org/200\
0/svg\x22 width=\x2224\
\x22 height=\x2224\x22 vi\
ewBox=\x220 0 24 24\
\x22><rect x=\x223\x22 y=\
\x222.5\x22 width=\x2210\x22\
 height=\x228\x22 rx=\x22\
1.5\x22 fill=\x22#8a96\
a3\x22 stroke=\x22#4a5\
25c\x22/><rect x=\x225\
\x22 y=\x224.5\x22 width=\
\x226\x22 height=\x223\x22 f\
ill=\x22#e7ecf1\x22/><\
path d=\x22M18.5 18\
H15V8\x22 fill=\x22non\
e\x22 stroke=\x22#e07b\
12\x22 stroke-width\
=\x222\x22/><path d=\x22M\
11 9h8l-4-5z\x22 fi\
ll=\x22#e07b12\x22 tra\
nsform=\x22translat\
e(0 1)\x22/><rect x\
=\x224\x22 y=\x2216\x22 widt\
h=\x2210\x22 height=\x226\
\x22 rx=\x221\x22 fill=\x22#\
f4f4f4\x22 stroke=\x22\
#5a6470\x22/></svg>\
\x0a\
\x00\x00\x01\xa2\
<\
svg xmlns=\x22http:\
//www.w3.org/200\
0/svg\x22 width=\x2224\
\x22 height=\x2224\x22 vi\
ewBox=\x220 0 24 24\
\x22><rect x=\x226\x22 y=\
\x222.5\x22 width=\x2212\x22\
 height=\x227\x22 fill\
=\x22#f4f4f4\x22 strok\
e=\x22#5a6470\x22/><re\
ct x=\x222.5\x22 y=\x229\x22\
 width=\x2219\x22 heig\
ht=\x229\x22 rx=\x221.5\x22 \
fill=\x22#8a96a3\x22 s\
troke=\x22#4a525c\x22/\
><rect x=\x226\x22 y=\x22\
14.5\x22 width=\x2212\x22\
 height=\x227\x22 fill\
=\x22#ffffff\x22 strok\
e=\x22#5a6470\x22/><pa\
th d=\x22M8 17h8M8 \
19h6\x22 stroke=\x22#5\
a6470\x22/><circle \
cx=\x2218.5\x22 cy=\x2211\
.5\x22 r=\x221\x22 fill=\x22\
#7bd88f\x22/></svg>\
\x0a\
\x00\x00\x00\xf9\
<\
svg xmlns=\x22http:\
//www.w3.org/200\
0/svg\x22 width=\x2224\
\x22 height=\x2224\x22 vi\
ewBox=\x220 0 24 24\
\x22><path d=\x22M18.4\
 8.5A7.5 7.5 0 1\
 0 19.5 13\x22 fill\
=\x22none\x22 stroke=\x22\
#d9443a\x22 stroke-\
width=\x222.4\x22 stro\
ke-linecap=\x22roun\
d\x22/><path d=\x22M14\
.5 8.8h5.6V3.2z\x22\
 fill=\x22#d9443a\x22/\
></svg>\x0a\
\x00\x00\x01\xb5\
<\
svg xmlns=\x22http:\
//www.w3.org/200\
0/svg\x22 width=\x2224\
\x22 height=\x2224\x22 vi\
ewBox=\x220 0 24 24\
\x22><rect x=\x221.5\x22 \
y=\x228.5\x22 width=\x226\
\x22 height=\x227\x22 fil\
l=\x22#e7ecf1\x22 stro\
ke=\x22#4a525c\x22/><r\
ect x=\x229.5\x22 y=\x228\
.5\x22 width=\x226\x22 he\
ight=\x227\x22 fill=\x22#\
e7ecf1\x22 stroke=\x22\
#4a525c\x22/><rect \
x=\x2217\x22 y=\x228.5\x22 w\
idth=\x225.5\x22 heigh\
t=\x227\x22 fill=\x22#e7e\
cf1\x22 stroke=\x22#4a\
525c\x22/><path d=\x22\
M7.5 12h2M15.5 1\
2h1.5\x22 stroke=\x22#\
2f7fd6\x22 stroke-w\
idth=\x221.6\x22/><cir\
cle cx=\x228.5\x22 cy=\
\x2212\x22 r=\x221.3\x22 fil\
l=\x22#d9443a\x22/></s\
vg>\x0a\
\x00\x00\x01>\
<\
svg xmlns=\x22http:\
//www.w3.org/200\
0/svg\x22 width=\x2224\
\x22 height=\x2224\x22 vi\
ewBox=\x220 0 24 24\
\x22><rect x=\x222.5\x22 \
y=\x224.5\x22 width=\x221\
9\x22 height=\x2215\x22 r\
x=\x222\x22 fill=\x22#e7e\
cf1\x22 stroke=\x22#4a\
525c\x22/><circle c\
x=\x227\x22 cy=\x2212\x22 r=\
\x222.5\x22 fill=\x22#3db\
b5a\x22/><circle cx\
=\x2212\x22 cy=\x2212\x22 r=\
\x222.5\x22 fill=\x22#d94\
43a\x22/><circle cx\
=\x2217\x22 cy=\x2212\x22 r=\
\x222.5\x22 fill=\x22#f0a\
020\x22/></svg>\x0a\
\x00\x00\x01)\
<\
svg xmlns=\x22http:\
//www.w3.org/200\
0/svg\x22 width=\x2224\
\x22 height=\x2224\x22 vi\
ewBox=\x220 0 24 24\
\x22><path d=\x22M3 12\
h5M16 12h5\x22 stro\
ke=\x22#2e9d47\x22 str\
oke-width=\x222.2\x22 \
stroke-linecap=\x22\
round\x22/><path d=\
\x22M8 7h4a5 5 0 0 \
1 0 10H8z\x22 fill=\
\x22#3dbb5a\x22 stroke\
=\x22#22753a\x22/><pat\
h d=\x22M16 9v6\x22 st\
roke=\x22#22753a\x22 s\
troke-width=\x222\x22/\
></svg>\x0a\
\x00\x00\x01\xcb\
<\
svg xmlns=\x22http:\
//www.w3.org/200\
0/svg\x22 width=\x2224\
\x22 height=\x2224\x22 vi\
ewBox=\x220 0 24 24\
\x22><rect x=\x222\x22 y=\
\x228\x22 width=\x2220\x22 h\
eight=\x229\x22 rx=\x221\x22\
 fill=\x22#b8c1cb\x22 \
stroke=\x22#4a525c\x22\
/><rect x=\x227\x22 y=\
\x228\x22 width=\x2210\x22 h\
eight=\x229\x22 fill=\x22\
#e7ecf1\x22 stroke=\
\x22#4a525c\x22/><path\
 d=\x22M9 10.5l6 4M\
15 10.5l-6 4\x22 st\
roke=\x22#2f7fd6\x22 s\
troke-width=\x221.5\
\x22/><rect x=\x229\x22 y\
=\x222.5\x22 width=\x226\x22\
 height=\x225.5\x22 rx\
=\x221\x22 fill=\x22#3dbb\
5a\x22 stroke=\x22#227\
53a\x22/><path d=\x22M\
8 17v4M16 17v4\x22 \
stroke=\x22#4a525c\x22\
 stroke-width=\x222\
\x22/></svg>\x0a\
\x00\x00\x01\xc5\
<\
svg xmlns=\x22http:\
//www.w3.org/200\
0/svg\x22 width=\x2224\
\x22 height=\x2224\x22 vi\
ewBox=\x220 0 24 24\
\x22><path d=\x22M2 7h\
20M2 17h20\x22 stro\
ke=\x22#4a525c\x22 str\
oke-width=\x221.8\x22/\
><path d=\x22M6 7v1\
0M12 7v10M18 7v1\
0\x22 stroke=\x22#8a96\
a3\x22 stroke-width\
=\x221.2\x22/><rect x=\
\x223.5\x22 y=\x229.5\x22 wi\
dth=\x225\x22 height=\x22\
5\x22 fill=\x22#e07b12\
\x22 stroke=\x22#8c4a0\
8\x22/><rect x=\x229.5\
\x22 y=\x229.5\x22 width=\
\x225\x22 height=\x225\x22 f\
ill=\x22#2f7fd6\x22 st\
roke=\x22#1d4f86\x22/>\
<rect x=\x2215.5\x22 y\
=\x229.5\x22 width=\x225\x22\
 height=\x225\x22 fill\
=\x22#3dbb5a\x22 strok\
e=\x22#22753a\x22/></s\
vg>\x0a\
\x00\x00\x02\x80\
<\
svg xmlns=\x22http:\
//www.w3.org/200\
0/svg\x22 width=\x2264\
\x22 height=\x2264\x22 vi\
ewBox=\x220 0 64 64\
\x22><rect x=\x224\x22 y=\
\x2222\x22 width=\x2256\x22 \
height=\x2224\x22 rx=\x22\
3\x22 fill=\x22#b8c1cb\
\x22 stroke=\x22#39424\
c\x22 stroke-width=\
\x222\x22/><rect x=\x2218\
\x22 y=\x2222\x22 width=\x22\
28\x22 height=\x2224\x22 \
fill=\x22#e7ecf1\x22 s\
troke=\x22#39424c\x22 \
stroke-width=\x222\x22\
/><path d=\x22M23 2\
8l18 12M41 28L23\
 40\x22 stroke=\x22#2f\
7fd6\x22 stroke-wid\
th=\x223\x22/><rect x=\
\x2222\x22 y=\x224\x22 width\
=\x2220\x22 height=\x2216\
\x22 rx=\x223\x22 fill=\x22#\
3dbb5a\x22 stroke=\x22\
#22753a\x22 stroke-\
width=\x222\x22/><text\
 x=\x2232\x22 y=\x2216\x22 f\
ont-family=\x22sans\
-serif\x22 font-siz\
e=\x229\x22 font-weigh\
t=\x22bold\x22 text-an\
chor=\x22middle\x22 fi\
ll=\x22#ffffff\x22>PRM\
9</text><path d=\
\x22M20 46v12M44 46\
v12\x22 stroke=\x22#39\
424c\x22 stroke-wid\
th=\x224\x22/></svg>\x0a\
\x00\x00\x01=\
<\
svg xmlns=\x22http:\
//www.w3.org/200\
0/svg\x22 width=\x2224\
\x22 height=\x2224\x22 vi\
ewBox=\x220 0 24 24\
\x22><rect x=\x222.5\x22 \
y=\x223.5\x22 width=\x221\
9\x22 height=\x2217\x22 f\
ill=\x22#ffffff\x22 st\
roke=\x22#4a525c\x22/>\
<rect x=\x222.5\x22 y=\
\x223.5\x22 width=\x2219\x22\
 height=\x224\x22 fill\
=\x22#8a96a3\x22 strok\
e=\x22#4a525c\x22/><pa\
th d=\x22M2.5 11.5h\
19M2.5 15.5h19M9\
 7.5v13M16 7.5v1\
3\x22 stroke=\x22#8a96\
a3\x22/></svg>\x0a\
\x00\x00\x01\xa8\
<\
svg xmlns=\x22http:\
//www.w3.org/200\
0/svg\x22 width=\x2224\
\x22 height=\x2224\x22 vi\
ewBox=\x220 0 24 24\
\x22><rect x=\x223\x22 y=\
\x222.5\x22 width=\x2210\x22\
 height=\x228\x22 rx=\x22\
1.5\x22 fill=\x22#8a96\
a3\x22 stroke=\x22#4a5\
25c\x22/><rect x=\x225\
\x22 y=\x224.5\x22 width=\
\x226\x22 height=\x223\x22 f\
ill=\x22#e7ecf1\x22/><\
path d=\x22M15 6h3.\
5v9\x22 fill=\x22none\x22\
 stroke=\x22#2f7fd6\
\x22 stroke-width=\x22\
2\x22/><path d=\x22M14\
.5 14h8l-4 5z\x22 f\
ill=\x22#2f7fd6\x22/><\
rect x=\x224\x22 y=\x2216\
\x22 width=\x2210\x22 hei\
ght=\x226\x22 rx=\x221\x22 f\
ill=\x22#f4f4f4\x22 st\
roke=\x22#5a6470\x22/>\
</svg>\x0a\
\x00\x00\x01\x94\
<\
svg xmlns=\x22http:\
//www.w3.org/200\
0/svg\x22 width=\x2224\
\x22 height=\x2224\x22 vi\
ewBox=\x220 0 24 24\
\x22><path d=\x22M2 12\
h4M18 12h4\x22 stro\
ke=\x22#8a96a3\x22 str\
oke-width=\x222.2\x22 \
stroke-linecap=\x22\
round\x22/><path d=\
\x22M6 7.5h3a4.5 4.\
5 0 0 1 0 9H6z\x22 \
fill=\x22#b8c1cb\x22 s\
troke=\x22#6b7682\x22/\
><path d=\x22M18 7.\
5h-3a4.5 4.5 0 0\
 0 0 9h3z\x22 fill=\
\x22#b8c1cb\x22 stroke\
=\x22#6b7682\x22/><pat\
h d=\x22M10 19l4-14\
\x22 stroke=\x22#d9443\
a\x22 stroke-width=\
\x222\x22 stroke-linec\
ap=\x22round\x22/></sv\
g>\x0a\
\x00\x00\x01G\
<\
svg xmlns=\x22http:\
//www.w3.org/200\
0/svg\x22 width=\x2224\
\x22 height=\x2224\x22 vi\
ewBox=\x220 0 24 24\
\x22><rect x=\x222\x22 y=\
\x223\x22 width=\x2220\x22 h\
eight=\x2216\x22 rx=\x221\
.5\x22 fill=\x22#26323\
8\x22 stroke=\x22#4a52\
5c\x22/><path d=\x22M4\
 14c2 0 2-7 4-7s\
2 9 4 9 2-6 4-6 \
2 3 4 3\x22 fill=\x22n\
one\x22 stroke=\x22#7b\
d88f\x22 stroke-wid\
th=\x221.6\x22/><path \
d=\x22M8 21h8\x22 stro\
ke=\x22#4a525c\x22 str\
oke-width=\x222\x22/><\
/svg>\x0a\
"

qt_resource_name = b"\
\x00\x05\
\x00o\xa6S\
\x00i\
\x00c\x00o\x00n\x00s\
\x00\x04\
\x00\x06\xec0\
\x00h\
\x00e\x00l\x00p\
\x00\x0c\
\x07\xbc\x97\x9c\
\x00h\
\x00e\x00l\x00p\x00_\x00c\x00s\x00.\x00h\x00t\x00m\x00l\
\x00\x0c\
\x07\xdc\x97\x9c\
\x00h\
\x00e\x00l\x00p\x00_\x00d\x00e\x00.\x00h\x00t\x00m\x00l\
\x00\x0c\
\x09\xcc\x97\x9c\
\x00h\
\x00e\x00l\x00p\x00_\x00e\x00n\x00.\x00h\x00t\x00m\x00l\
\x00\x0a\
\x05x\xd4\xa7\
\x00u\
\x00p\x00l\x00o\x00a\x00d\x00.\x00s\x00v\x00g\
\x00\x09\
\x00W\xb5\xe7\
\x00p\
\x00r\x00i\x00n\x00t\x00.\x00s\x00v\x00g\
\x00\x0b\
\x08f\xcf\x87\
\x00r\
\x00e\x00s\x00t\x00a\x00r\x00t\x00.\x00s\x00v\x00g\
\x00\x0b\
\x08\xad\xb5\x07\
\x00d\
\x00i\x00a\x00g\x00r\x00a\x00m\x00.\x00s\x00v\x00g\
\x00\x0a\
\x0b\xcd\x0f\xc7\
\x00s\
\x00t\x00a\x00t\x00u\x00s\x00.\x00s\x00v\x00g\
\x00\x0a\
\x00J\x90\xa7\
\x00o\
\x00n\x00l\x00i\x00n\x00e\x00.\x00s\x00v\x00g\
\x00\x09\
\x03\xc8\xa3\xc7\
\x00v\
\x00a\x00l\x00v\x00e\x00.\x00s\x00v\x00g\
\x00\x0b\
\x06\x92P\x07\
\x00c\
\x00a\x00n\x00o\x00p\x00e\x00n\x00.\x00s\x00v\x00g\
\x00\x07\
\x08sZ\x07\
\x00a\
\x00p\x00p\x00.\x00s\x00v\x00g\
\x00\x0e\
\x0d\x86>'\
\x00p\
\x00a\x00r\x00a\x00m\x00e\x00t\x00e\x00r\x00s\x00.\x00s\x00v\x00g\
\x00\x0c\
\x08\x1a\x90\xa7\
\x00d\
\x00o\x00w\x00n\x00l\x00o\x00a\x00d\x00.\x00s\x00v\x00g\
\x00\x0b\
\x00\xaf\xc0\xa7\
\x00o\
\x00f\x00f\x00l\x00i\x00n\x00e\x00.\x00s\x00v\x00g\
\x00\x09\
\x06h\xa9\x87\
\x00s\
\x00c\x00o\x00p\x00e\x00.\x00s\x00v\x00g\
"

qt_resource_struct = b"\
\x00\x00\x00\x00\x00\x02\x00\x00\x00\x02\x00\x00\x00\x01\
\x00\x00\x00\x10\x00\x02\x00\x00\x00\x03\x00\x00\x00\x10\
\x00\x00\x00\x00\x00\x02\x00\x00\x00\x0d\x00\x00\x00\x03\
\x00\x00\x00\xfc\x00\x00\x00\x00\x00\x01\x00\x00<\x0c\
\x00\x00\x00\x92\x00\x00\x00\x00\x00\x01\x00\x006n\
\x00\x00\x01\x9e\x00\x00\x00\x00\x00\x01\x00\x00FB\
\x00\x00\x01\x16\x00\x00\x00\x00\x00\x01\x00\x00=9\
\x00\x00\x00x\x00\x00\x00\x00\x00\x01\x00\x004\xa8\
\x00\x00\x01\xba\x00\x00\x00\x00\x00\x01\x00\x00G\xda\
\x00\x00\x01.\x00\x00\x00\x00\x00\x01\x00\x00?\x08\
\x00\x00\x01\x80\x00\x00\x00\x00\x00\x01\x00\x00D\x96\
\x00\x00\x00\xaa\x00\x00\x00\x00\x00\x01\x00\x008\x14\
\x00\x00\x01J\x00\x00\x00\x00\x00\x01\x00\x00@\xd1\
\x00\x00\x00\xc6\x00\x00\x00\x00\x00\x01\x00\x009\x11\
\x00\x00\x00\xe2\x00\x00\x00\x00\x00\x01\x00\x00:\xca\
\x00\x00\x01^\x00\x00\x00\x00\x00\x01\x00\x00CU\
\x00\x00\x00\x1e\x00\x00\x00\x00\x00\x01\x00\x00\x00\x00\
\x00\x00\x00<\x00\x00\x00\x00\x00\x01\x00\x00\x12\x1e\
\x00\x00\x00Z\x00\x00\x00\x00\x00\x01\x00\x00$\x94\
"


def qInitResources():
    QtCore.qRegisterResourceData(0x01, qt_resource_struct, qt_resource_name, qt_resource_data)


def qCleanupResources():
    QtCore.qUnregisterResourceData(0x01, qt_resource_struct, qt_resource_name, qt_resource_data)


qInitResources()
