# Resource object code (Python 3)
# Created by: object code
# Created by: The Resource Compiler for Qt version 6.11.3
# WARNING! All changes made in this file will be lost!

from PySide6 import QtCore

qt_resource_data = b"\
\x00\x00\x17\x8a\
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
 hash.</p>\x0a<p>\xc3\x9a\
rovn\xc4\x9b opr\xc3\xa1vn\xc4\x9b\
n\xc3\xad chr\xc3\xa1n\xc3\xad p\xc5\x99\
ed ne\xc3\xbamysln\xc3\xbdmi\
 zm\xc4\x9bnami, ne p\xc5\
\x99ed t\xc3\xadm, kdo m\xc5\
\xaf\xc5\xbee upravovat n\
astaven\xc3\xad\x0aprogra\
mu: odstran\xc4\x9bn\xc3\xad\
m polo\xc5\xbeky <code\
>access/expert_p\
assword</code> z\
 nastaven\xc3\xad plat\
\xc3\xad op\xc4\x9bt heslo\x0ap\
\xc5\x99i dod\xc3\xa1n\xc3\xad. So\
ubor parametr\xc5\xaf \
obsahuje v\xc5\xa1echn\
y hodnoty bez oh\
ledu na \xc3\xbarove\xc5\x88\
: pokud u\xc5\xbeivate\
l na\x0az\xc3\xa1kladn\xc3\xad \
\xc3\xbarovni odes\xc3\xadl\xc3\
\xa1 dokument, jeho\
\xc5\xbe hodnoty exper\
tn\xc3\xad \xc3\xbarovn\xc4\x9b se\
 li\xc5\xa1\xc3\xad od hodno\
t ventilu,\x0aprogr\
am se nejprve ze\
pt\xc3\xa1.</p>\x0a\x0a<h2>O\
nline a offline<\
/h2>\x0a<p>Komunika\
ce \xe2\x86\x92 Konfigura\
ce HID zobraz\xc3\xad \
ventily p\xc5\x99ipoje\
n\xc3\xa9 p\xc5\x99es USB a \
emulovan\xc3\xa9 venti\
ly;\x0aemulovan\xc3\xbd v\
entil p\xc5\x99id\xc3\xa1te \
zad\xc3\xa1n\xc3\xadm typov\xc3\
\xa9ho kl\xc3\xad\xc4\x8de a v\xc3\
\xbdrobn\xc3\xadho \xc4\x8d\xc3\xadsl\
a. Komunikace \xe2\x86\
\x92 Re\xc5\xbeim online\x0a\
nav\xc3\xa1\xc5\xbee spojen\xc3\
\xad. Dokument na\xc4\x8d\
ten\xc3\xbd z jin\xc3\xa9ho \
ventilu (jin\xc3\xa9 v\
\xc3\xbdrobn\xc3\xad \xc4\x8d\xc3\xadslo\
) program nejprv\
e ohl\xc3\xa1s\xc3\xad: pokr\
a\xc4\x8dovat s n\xc3\xadm, \
nebo p\xc5\x99ej\xc3\xadt do\
 re\xc5\xbeimu offline\
. Li\xc5\xa1\xc3\xad-li se o\
tev\xc5\x99en\xc3\xbd z\xc3\xa1zna\
m parametr\xc5\xaf od \
ventilu, program\
 zobraz\xc3\xad rozd\xc3\xad\
ly a\x0azept\xc3\xa1 se, \
zda p\xc5\x99evz\xc3\xadt ho\
dnoty ventilu, o\
deslat hodnoty d\
okumentu (na\xc4\x8dte\
n\xc3\xad do ventilu) \
nebo\x0azru\xc5\xa1it. V \
re\xc5\xbeimu online j\
de ka\xc5\xbed\xc3\xa1 zm\xc4\x9bn\
a ihned do venti\
lu i do dokument\
u, v re\xc5\xbeimu off\
line\x0apouze do do\
kumentu. Ztrat\xc3\xad\
-li se spojen\xc3\xad \
s ventilem, prog\
ram p\xc5\x99ejde do r\
e\xc5\xbeimu offline a\
\x0av\xc5\xa1echny hodnot\
y zachov\xc3\xa1.</p>\x0a\
<p>Hodnoty zm\xc4\x9bn\
\xc4\x9bn\xc3\xa9 online jso\
u ve ventilu akt\
ivn\xc3\xad, ale je\xc5\xa1t\
\xc4\x9b neulo\xc5\xbeen\xc3\xa9: \
p\xc5\x99i p\xc5\x99echodu d\
o\x0are\xc5\xbeimu offlin\
e program nab\xc3\xadd\
ne jejich ulo\xc5\xbee\
n\xc3\xad a Ventil \xe2\x86\x92\
 <b>Ulo\xc5\xbeit do p\
am\xc4\x9bti ventilu</\
b> je ulo\xc5\xbe\xc3\xad\x0ahn\
ed (s \xc4\x8d\xc3\xadm vent\
il pracuje, s t\xc3\
\xadm i nastartuje;\
 zaznamen\xc3\xa1 se d\
o historie). <b>\
Na\xc4\x8dten\xc3\xad do ven\
tilu</b> zap\xc3\xad\xc5\xa1\
e v\xc5\xa1echny\x0ahodno\
ty, p\xc5\x99e\xc4\x8dte je \
zp\xc4\x9bt, porovn\xc3\xa1 \
a ulo\xc5\xbe\xc3\xad; ulo\xc5\xbe\
\xc3\xad se jen tehdy,\
 je-li ka\xc5\xbed\xc3\xa1 h\
odnota ov\xc4\x9b\xc5\x99ena\
.\x0aP\xc5\x99ed prvn\xc3\xadm \
na\xc4\x8dten\xc3\xadm do ve\
ntilu program ul\
o\xc5\xbe\xc3\xad z\xc3\xa1lohu vl\
astn\xc3\xadch paramet\
r\xc5\xaf ventilu do s\
lo\xc5\xbeky\x0au\xc5\xbeivatel\
sk\xc3\xbdch dat (<cod\
e>backups/&lt;v\xc3\
\xbdrobn\xc3\xad \xc4\x8d\xc3\xadslo&\
gt;/</code>).</p\
>\x0a<p><b>Restart \
ventilu</b> a <b\
>Obnoven\xc3\xad tov\xc3\xa1\
rn\xc3\xadho nastaven\xc3\
\xad</b> jsou dovol\
eny pouze p\xc5\x99i\x0ao\
dpojen\xc3\xa9m hydrau\
lick\xc3\xa9m obvodu; \
program v\xc3\xa1s po\xc5\
\xbe\xc3\xa1d\xc3\xa1 o potvrze\
n\xc3\xad.</p>\x0a\x0a<h2>So\
ubory</h2>\x0a<p>Z\xc3\
\xa1znamy parametr\xc5\
\xaf (<code>*.prm</\
code>) jsou text\
ov\xc3\xa9 soubory. Ot\
ev\xc5\x99\xc3\xadt, Ulo\xc5\xbeit\
, Ulo\xc5\xbeit jako,\x0a\
naposledy otev\xc5\x99\
en\xc3\xa9 soubory a p\
\xc5\x99eta\xc5\xbeen\xc3\xad my\xc5\xa1\
\xc3\xad funguj\xc3\xad obvy\
kl\xc3\xbdm zp\xc5\xafsobem;\
 p\xc5\x99ed ztr\xc3\xa1tou\x0a\
neulo\xc5\xbeen\xc3\xbdch zm\
\xc4\x9bn se program z\
ept\xc3\xa1. Ka\xc5\xbedou z\
m\xc4\x9bnu lze vr\xc3\xa1ti\
t (Ctrl+Z) a zno\
vu prov\xc3\xa9st\x0a(Ctr\
l+Y). Soubor \xe2\x86\x92\
 Tisk a Soubor \xe2\
\x86\x92 Export do PDF\
 vytvo\xc5\x99\xc3\xad proto\
kol parametr\xc5\xaf s\
 typov\xc3\xbdm kl\xc3\xad\xc4\x8d\
em,\x0av\xc3\xbdrobn\xc3\xadm \xc4\
\x8d\xc3\xadslem, firmwar\
e, souborem, dat\
em, \xc3\xbarovn\xc3\xad opr\
\xc3\xa1vn\xc4\x9bn\xc3\xad, postu\
pov\xc3\xbdm diagramem\
 a v\xc5\xa1emi\x0aparame\
try s jednotkami\
. Hodnoty zm\xc4\x9bn\xc4\
\x9bn\xc3\xa9 od ulo\xc5\xbeen\xc3\
\xad souboru jsou o\
zna\xc4\x8deny <b>*</b\
> a \xc5\x99\xc3\xa1dek\x0a\xe2\x80\x9eS\
oubor\xe2\x80\x9c to uv\xc3\xa1\
d\xc3\xad; ka\xc5\xbed\xc3\xa1 str\
ana uv\xc3\xa1d\xc3\xad typo\
v\xc3\xbd kl\xc3\xad\xc4\x8d a v\xc3\xbd\
robn\xc3\xad \xc4\x8d\xc3\xadslo a\
 sv\xc3\xa9 \xc4\x8d\xc3\xadslo st\
rany; na\x0aposledn\
\xc3\xad stran\xc4\x9b je \xc5\x99\
\xc3\xa1dek pro datum,\
 jm\xc3\xa9no a podpis\
.</p>\x0a<p><b>Z\xc3\xa1l\
oha ventilu</b>:\
 p\xc5\x99ipojte se (r\
e\xc5\xbeim online), V\
entil \xe2\x86\x92 Sta\xc5\xbee\
n\xc3\xad z ventilu, p\
ak\x0aSoubor \xe2\x86\x92 <b\
>Ulo\xc5\xbeit z\xc3\xa1lo\xc5\xbe\
n\xc3\xad kopii\xe2\x80\xa6</b>\
 (navr\xc5\xbeen\xc3\xbd n\xc3\xa1\
zev: typov\xc3\xbd kl\xc3\
\xad\xc4\x8d, v\xc3\xbdrobn\xc3\xad \xc4\
\x8d\xc3\xadslo, datum\x0aa \
\xc4\x8das). Kopie se \
zap\xc3\xad\xc5\xa1e a otev\xc5\
\x99en\xc3\xbd dokument z\
\xc5\xafstane, jak\xc3\xbd b\
yl: pozd\xc4\x9bj\xc5\xa1\xc3\xad \
zm\xc4\x9bny se ukl\xc3\xa1d\
aj\xc3\xad do\x0ajeho vla\
stn\xc3\xadho souboru,\
 nikdy do z\xc3\xa1loh\
y. Naproti tomu \
Ulo\xc5\xbeit jako ud\xc4\
\x9bl\xc3\xa1 z nov\xc3\xa9ho s\
ouboru\x0aotev\xc5\x99en\xc3\
\xbd dokument.</p>\x0a\
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
ilu / Konfigurac\
e HID</td></tr>\x0a\
</table>\x0a</body>\
\x0a</html>\x0a\
\x00\x00\x18\x14\
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
p>\x0a<p>Die Berech\
tigungsstufen sc\
h\xc3\xbctzen vor vers\
ehentlichen \xc3\x84nd\
erungen, nicht v\
or jemandem, der\
 die\x0aEinstellung\
en des Programms\
 bearbeiten kann\
: Wird der Eintr\
ag\x0a<code>access/\
expert_password<\
/code> aus den E\
instellungen ent\
fernt, gilt wied\
er das Passwort\x0a\
des Auslieferung\
szustands. Eine \
Parameterdatei e\
nth\xc3\xa4lt alle Wer\
te, unabh\xc3\xa4ngig \
von der Stufe:\x0aS\
endet ein Benutz\
er der Stufe Bas\
is ein Dokument,\
 dessen Experten\
werte von denen \
des Ventils\x0aabwe\
ichen, fragt das\
 Programm zuerst\
 nach.</p>\x0a\x0a<h2>\
Online und offli\
ne</h2>\x0a<p>Kommu\
nikation \xe2\x86\x92 HID\
-Konfiguration l\
istet die \xc3\xbcber \
USB angeschlosse\
nen und die emul\
ierten\x0aVentile; \
ein emuliertes V\
entil f\xc3\xbcgen Sie\
 mit Typschl\xc3\xbcss\
el und Seriennum\
mer hinzu.\x0aKommu\
nikation \xe2\x86\x92 Onl\
ine-Modus verbin\
det. Ein aus ein\
em anderen Venti\
l (andere Serien\
nummer) gelesene\
s Dokument wird \
zuerst genannt: \
damit weiterarbe\
iten oder offlin\
e gehen. Weicht \
der ge\xc3\xb6ffnete P\
arametersatz vom\
 Ventil ab,\x0azeig\
t das Programm d\
ie Unterschiede \
und fragt, ob di\
e Werte des Vent\
ils \xc3\xbcbernommen,\
 die\x0aWerte des D\
okuments gesende\
t (Hochladen) od\
er abgebrochen w\
erden soll. Onli\
ne geht jede\x0a\xc3\x84n\
derung sofort an\
 das Ventil und \
in das Dokument,\
 offline nur in \
das Dokument. Ge\
ht die\x0aVerbindun\
g verloren, scha\
ltet das Program\
m auf offline un\
d beh\xc3\xa4lt alle W\
erte.</p>\x0a<p>Onl\
ine ge\xc3\xa4nderte W\
erte sind im Ven\
til aktiv, aber \
noch nicht gespe\
ichert: beim Wec\
hsel\x0aauf offline\
 bietet das Prog\
ramm an, sie zu \
speichern, und V\
entil \xe2\x86\x92 <b>Im \
Ventil speichern\
</b>\x0aspeichert s\
ie sofort (womit\
 das Ventil arbe\
itet, damit star\
tet es auch; im \
Verlauf\x0afestgeha\
lten). <b>In das\
 Ventil hochlade\
n</b>\x0aschreibt a\
lle Werte, liest\
 sie zur\xc3\xbcck, ve\
rgleicht und spe\
ichert sie; gesp\
eichert wird nur\
,\x0awenn jeder Wer\
t best\xc3\xa4tigt wur\
de. Vor dem erst\
en Hochladen in \
ein Ventil siche\
rt das\x0aProgramm \
dessen eigene Pa\
rameter im Benut\
zerdatenordner (\
<code>backups/&l\
t;Seriennummer&g\
t;/</code>).</p>\
\x0a<p><b>Ventil ne\
u starten</b> un\
d <b>Werkseinste\
llungen wiederhe\
rstellen</b> sin\
d nur bei\x0agetren\
nter Hydraulik e\
rlaubt; das Prog\
ramm l\xc3\xa4sst Sie \
das best\xc3\xa4tigen.\
</p>\x0a\x0a<h2>Dateie\
n</h2>\x0a<p>Parame\
terdateien (<cod\
e>*.prm</code>) \
sind Textdateien\
. \xc3\x96ffnen, Speic\
hern, Speichern\x0a\
unter, die zulet\
zt ge\xc3\xb6ffneten D\
ateien und Drag \
&amp; Drop funkt\
ionieren wie gew\
ohnt; vor dem\x0aVe\
rlust ungespeich\
erter \xc3\x84nderunge\
n fragt das Prog\
ramm nach. Jede \
\xc3\x84nderung l\xc3\xa4sst\
 sich\x0ar\xc3\xbcckg\xc3\xa4ng\
ig machen (Strg+\
Z) und wiederher\
stellen (Strg+Y)\
. Datei \xe2\x86\x92 Druc\
ken und Datei \xe2\x86\
\x92 PDF\x0aexportiere\
n erzeugen ein P\
arameterprotokol\
l mit Typschl\xc3\xbcs\
sel, Seriennumme\
r, Firmware, Dat\
ei,\x0aDatum, Berec\
htigungsstufe, d\
em Ablaufdiagram\
m und allen Para\
metern mit Einhe\
it. Seit dem\x0aSpe\
ichern ge\xc3\xa4ndert\
e Werte sind mit\
 <b>*</b> markie\
rt, und die Zeil\
e \xe2\x80\x9eDatei\xe2\x80\x9c sa\
gt es; jede Seit\
e\x0anennt Typschl\xc3\
\xbcssel und Serien\
nummer und tr\xc3\xa4g\
t ihre Seitenzah\
l; die letzte Se\
ite hat eine Zei\
le\x0af\xc3\xbcr Datum, N\
ame und Untersch\
rift.</p>\x0a<p><b>\
Ein Ventil siche\
rn</b>: online g\
ehen, Ventil \xe2\x86\x92\
 Aus dem Ventil \
herunterladen, d\
ann\x0aDatei \xe2\x86\x92 <b\
>Sicherungskopie\
 speichern\xe2\x80\xa6</b\
> (vorgeschlagen\
er Name: Typschl\
\xc3\xbcssel, Seriennu\
mmer,\x0aDatum und \
Uhrzeit). Die Ko\
pie wird geschri\
eben, das ge\xc3\xb6ff\
nete Dokument bl\
eibt, was es war\
:\x0asp\xc3\xa4tere \xc3\x84nde\
rungen werden in\
 seine eigene Da\
tei gespeichert,\
 nie in die Sich\
erung. Speichern\
\x0aunter dagegen m\
acht die neue Da\
tei zum ge\xc3\xb6ffne\
ten Dokument.</p\
>\x0a\x0a<h2>Tastatur<\
/h2>\x0a<table>\x0a<tr\
><td>Strg+O / St\
rg+S / Strg+Umsc\
halt+S</td><td>\xc3\
\x96ffnen / Speiche\
rn / Speichern u\
nter</td></tr>\x0a<\
tr><td>Strg+Z / \
Strg+Y</td><td>R\
\xc3\xbcckg\xc3\xa4ngig / Wi\
ederherstellen</\
td></tr>\x0a<tr><td\
>Strg+P / Strg+E\
</td><td>Drucken\
 / PDF exportier\
en</td></tr>\x0a<tr\
><td>Strg+1 / St\
rg+2 / Strg+3 / \
Strg+4</td><td>A\
blaufdiagramm / \
Parameterliste /\
 Oszilloskop / C\
ANopen-Fenster</\
td></tr>\x0a<tr><td\
>F5 / Umschalt+F\
5</td><td>Online\
 / Offline</td><\
/tr>\x0a<tr><td>Str\
g+U / Strg+D</td\
><td>In das Vent\
il hochladen / A\
us dem Ventil he\
runterladen</td>\
</tr>\x0a<tr><td>St\
rg+T / Strg+I / \
Strg+H</td><td>V\
entilauswahl / V\
entilstatus / HI\
D-Konfiguration<\
/td></tr>\x0a</tabl\
e>\x0a</body>\x0a</htm\
l>\x0a\
\x00\x00\x14\xca\
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
of it.</p>\x0a<p>Th\
e access levels \
guard against ac\
cidental changes\
, not against so\
meone who can ed\
it the\x0aprogram's\
 settings: remov\
ing the entry <c\
ode>access/exper\
t_password</code\
> from the setti\
ngs\x0abrings back \
the delivered pa\
ssword. A parame\
ter file carries\
 every value wha\
tever the level:\
\x0aat Basic level,\
 sending a docum\
ent whose Expert\
-level values di\
ffer from the va\
lve's asks\x0afirst\
.</p>\x0a\x0a<h2>Onlin\
e and offline</h\
2>\x0a<p>Communicat\
ion \xe2\x86\x92 HID conf\
iguration lists \
the valves conne\
cted over USB an\
d the emulated\x0av\
alves; add an em\
ulated valve wit\
h its type key a\
nd serial number\
. Communication \
\xe2\x86\x92 Online\x0amode \
connects. A docu\
ment read from a\
nother valve (an\
other serial num\
ber) is named fi\
rst: go on with \
it, or go offlin\
e. If the open p\
arameter set dif\
fers from the va\
lve's, the progr\
am lists the\x0adif\
ferences and ask\
s whether to tak\
e the valve's va\
lues, send the d\
ocument's values\
\x0a(upload) or can\
cel. Online, eve\
ry change goes t\
o the valve at o\
nce and into the\
 document;\x0aoffli\
ne, into the doc\
ument only. If t\
he valve is lost\
, the program go\
es offline and k\
eeps\x0aevery value\
.</p>\x0a<p>Values \
changed online a\
re active in the\
 valve but not y\
et stored: going\
 offline offers \
to\x0astore them, a\
nd Valve \xe2\x86\x92 <b>\
Store in valve</\
b> stores them a\
t once (what the\
 valve works wit\
h\x0abecomes what i\
t starts with; r\
ecorded in the h\
istory). <b>Uplo\
ad to valve</b> \
writes all value\
s, reads them ba\
ck, compares and\
 stores\x0athem; no\
thing is stored \
unless every val\
ue was verified.\
 Before the firs\
t upload to a va\
lve\x0athe program \
saves a backup o\
f the valve's ow\
n parameters in \
the user data fo\
lder\x0a(<code>back\
ups/&lt;serial&g\
t;/</code>).</p>\
\x0a<p><b>Restart v\
alve</b> and <b>\
Restore factory \
values</b> are a\
llowed only with\
 the\x0ahydraulics \
disconnected; th\
e program asks y\
ou to confirm th\
is.</p>\x0a\x0a<h2>Fil\
es</h2>\x0a<p>Param\
eter files (<cod\
e>*.prm</code>) \
are text files. \
Open, Save, Save\
 As, the recent\x0a\
files and drag a\
nd drop work as \
usual; the progr\
am asks before u\
nsaved changes a\
re lost.\x0aEvery c\
hange can be und\
one (Ctrl+Z) and\
 redone (Ctrl+Y)\
. File \xe2\x86\x92 Print\
 and File \xe2\x86\x92 Ex\
port PDF\x0aproduce\
 a parameter rec\
ord with type ke\
y, serial number\
, firmware, file\
, date, access l\
evel,\x0athe flow d\
iagram and every\
 parameter with \
its unit. Values\
 changed since t\
he file was save\
d\x0aare marked <b>\
*</b> and the fi\
le line says so;\
 every page name\
s the type key a\
nd serial\x0anumber\
 and carries its\
 page number; th\
e last page has \
a line for date,\
 name and\x0asignat\
ure.</p>\x0a<p><b>B\
ack up a valve</\
b>: go online, V\
alve \xe2\x86\x92 Downloa\
d from valve, th\
en File \xe2\x86\x92 <b>S\
ave backup\x0acopy\xe2\
\x80\xa6</b> (proposed\
 name: type key,\
 serial number, \
date and time). \
The copy is writ\
ten and\x0athe open\
 document stays \
what it was: lat\
er changes are s\
aved into the do\
cument's own fil\
e,\x0anever into th\
e backup. Save A\
s, by contrast, \
makes the new fi\
le the open docu\
ment.</p>\x0a\x0a<h2>K\
eyboard</h2>\x0a<ta\
ble>\x0a<tr><td>Ctr\
l+O / Ctrl+S / C\
trl+Shift+S</td>\
<td>Open / Save \
/ Save As</td></\
tr>\x0a<tr><td>Ctrl\
+Z / Ctrl+Y</td>\
<td>Undo / Redo<\
/td></tr>\x0a<tr><t\
d>Ctrl+P / Ctrl+\
E</td><td>Print \
/ Export PDF</td\
></tr>\x0a<tr><td>C\
trl+1 / Ctrl+2 /\
 Ctrl+3 / Ctrl+4\
</td><td>Flow di\
agram / Paramete\
r list / Oscillo\
scope / CANopen \
window</td></tr>\
\x0a<tr><td>F5 / Sh\
ift+F5</td><td>O\
nline / Offline<\
/td></tr>\x0a<tr><t\
d>Ctrl+U / Ctrl+\
D</td><td>Upload\
 to valve / Down\
load from valve<\
/td></tr>\x0a<tr><t\
d>Ctrl+T / Ctrl+\
I / Ctrl+H</td><\
td>Valve selecti\
on / Valve statu\
s / HID configur\
ation</td></tr>\x0a\
</table>\x0a</body>\
\x0a</html>\x0a\
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
\x00\x00\x00\xfc\x00\x00\x00\x00\x00\x01\x00\x00K\xd8\
\x00\x00\x00\x92\x00\x00\x00\x00\x00\x01\x00\x00F:\
\x00\x00\x01\x9e\x00\x00\x00\x00\x00\x01\x00\x00V\x0e\
\x00\x00\x01\x16\x00\x00\x00\x00\x00\x01\x00\x00M\x05\
\x00\x00\x00x\x00\x00\x00\x00\x00\x01\x00\x00Dt\
\x00\x00\x01\xba\x00\x00\x00\x00\x00\x01\x00\x00W\xa6\
\x00\x00\x01.\x00\x00\x00\x00\x00\x01\x00\x00N\xd4\
\x00\x00\x01\x80\x00\x00\x00\x00\x00\x01\x00\x00Tb\
\x00\x00\x00\xaa\x00\x00\x00\x00\x00\x01\x00\x00G\xe0\
\x00\x00\x01J\x00\x00\x00\x00\x00\x01\x00\x00P\x9d\
\x00\x00\x00\xc6\x00\x00\x00\x00\x00\x01\x00\x00H\xdd\
\x00\x00\x00\xe2\x00\x00\x00\x00\x00\x01\x00\x00J\x96\
\x00\x00\x01^\x00\x00\x00\x00\x00\x01\x00\x00S!\
\x00\x00\x00\x1e\x00\x00\x00\x00\x00\x01\x00\x00\x00\x00\
\x00\x00\x00<\x00\x00\x00\x00\x00\x01\x00\x00\x17\x8e\
\x00\x00\x00Z\x00\x00\x00\x00\x00\x01\x00\x00/\xa6\
"

def qInitResources():
    QtCore.qRegisterResourceData(0x01, qt_resource_struct, qt_resource_name, qt_resource_data)

def qCleanupResources():
    QtCore.qUnregisterResourceData(0x01, qt_resource_struct, qt_resource_name, qt_resource_data)

qInitResources()
