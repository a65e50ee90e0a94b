never  {    /* !(a U (b V !c)) */
T0_init:
	do
	:: ((c)) -> goto accept_S9
	:: atomic { (! ((a)) && (c)) -> assert(!(! ((a)) && (c))) }
	:: (! ((a)) && ! ((b))) -> goto T0_S21
	od;
accept_S9:
	if
	:: (1) -> goto T0_init
	:: p
	fi;
T0_S21:
	false;
accept_all:
	skip
}
